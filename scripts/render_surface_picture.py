#!/usr/bin/env python3
"""Renders a water-surface PLY (tidepool render ... --export surface) offscreen with VTK to a PNG:
render_surface_picture.py SURFACE.ply OUT.png [OBSTACLES.ply]. Needs python3-vtk9 and a display (run it
under xvfb-run -a on a headless machine)."""
import sys
import vtk

def actor(path, color):
    reader = vtk.vtkPLYReader()
    reader.SetFileName(path)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    a.GetProperty().SetColor(*color)
    a.GetProperty().SetSpecular(0.4)
    a.GetProperty().SetSpecularPower(30)
    return a, reader

renderer = vtk.vtkRenderer()
renderer.SetBackground(0.93, 0.94, 0.96)
water, reader = actor(sys.argv[1], (0.25, 0.5, 0.85))
renderer.AddActor(water)
if len(sys.argv) > 3:
    renderer.AddActor(actor(sys.argv[3], (0.7, 0.7, 0.7))[0])
window = vtk.vtkRenderWindow()
window.SetSize(1200, 675)
window.AddRenderer(renderer)
window.Render()  # the pipeline runs: the camera can frame its bounds
camera = renderer.GetActiveCamera()
x0, x1, y0, y1, z0, z1 = reader.GetOutput().GetBounds()
centre = ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2)
camera.SetFocalPoint(*centre)
camera.SetPosition(centre[0] + 0.9, centre[1] - 1.6, centre[2] + 1.0)  # from the front, left, above (z up)
camera.SetViewUp(0, 0, 1)
renderer.ResetCamera()
camera.Zoom(1.3)
renderer.ResetCameraClippingRange()
window.Render()
shot = vtk.vtkWindowToImageFilter()
shot.SetInput(window)
shot.ReadFrontBufferOff()
shot.Update()
writer = vtk.vtkPNGWriter()
writer.SetFileName(sys.argv[2])
writer.SetInputConnection(shot.GetOutputPort())
writer.Write()
print(f"{sys.argv[2]}: {reader.GetOutput().GetNumberOfPolys()} triangles")
