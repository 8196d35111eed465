// Measurements of the ripples model against theory, shared by the tests and `tidepool sweep`:
//   phase speed  c̃/c = 2·asin(C·S)/(C·kΔx), S² = sin²(k_xΔx/2) + sin²(k_yΔx/2)
//   stability    bounded growth of random noise, bisected over C (or dt for the seed rule)
#pragma once

#include <functional>

#include "gl/shader_library.h"
#include "sim/measure/bisect.h"
#include "sim/ripples/ripples_params.h"

namespace tidepool::ripples {

// Wave rule on a periodic, undamped grid of the given size (everything else default).
Params periodicWaveGrid(int width, int height);

// Predicted phase-speed ratio c̃/c for wavenumbers (radians per cell) at Courant number C.
double predictedPhaseRatio(double kx, double ky, double courant);

// Measured c̃/c of the standing wave cos(kx·x + ky·y) on a width x height torus (the wave must fit
// it). The leapfrog recurrence a[n+1] + a[n-1] = 2·cos(θ)·a[n] holds exactly for the mode's
// amplitude; θ = ω̃·Δt is fitted by least squares over `periods` periods.
double measuredPhaseRatio(gl::ShaderLibrary& shaders, int width, int height, double kx, double ky, double courant,
                          double periods = 4.0);

// Growth of random noise (max |h| / start) after `steps` steps of dt; infinity on NaN/inf or
// once it passes `giveUp` (checked every 500 steps, so unstable runs end early).
double noiseGrowth(gl::ShaderLibrary& shaders, const Params& params, double dt, int steps, double giveUp = 100.0);

}  // namespace tidepool::ripples
