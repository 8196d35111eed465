# ParaView (pvpython) screenshot of a tidepool export: the water surface (surface.pvd) over the
# particles (particles.pvd) coloured by speed, at the last exported time.
import sys
from paraview.simple import *
surface_pvd, particles_pvd, out = sys.argv[1], sys.argv[2], sys.argv[3]
surface = PVDReader(FileName=surface_pvd)
particles = PVDReader(FileName=particles_pvd)
times = surface.TimestepValues
view = CreateView('RenderView')
view.ViewSize = [1200, 675]
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 1
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = float(list(times)[-1])
s = Show(surface, view)
s.Representation = 'Surface'
s.ColorArrayName = ["POINTS", ""]
s.DiffuseColor = [0.2, 0.45, 0.85]
s.Opacity = 0.7
calc = Calculator(Input=particles)
calc.ResultArrayName = 'speed'
calc.Function = 'mag(velocity)'
p = Show(calc, view)
p.Representation = 'Points'
p.PointSize = 2
ColorBy(p, ('POINTS', 'speed'))
lut = GetColorTransferFunction('speed')
lut.ApplyPreset('Viridis (matplotlib)', True)
p.SetScalarBarVisibility(view, True)
outline = Show(Outline(Input=surface), view)
outline.DiffuseColor = [0.3, 0.3, 0.3]
view.CameraPosition = [1.3, -0.9, 0.9]
view.CameraFocalPoint = [0.5, 0.12, 0.15]
view.CameraViewUp = [0, 0, 1]
view.ResetCamera(False)
GetActiveCamera().Dolly(1.35)
Render(view)
SaveScreenshot(out, view, ImageResolution=[1200, 675])
