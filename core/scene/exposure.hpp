#pragma once

// Physical camera exposure: what a camera's exposure value does to scene luminance before tone mapping.
namespace pbr {

// EV100 beyond this is no camera setting (a sunny day is about 15, moonlight about -2): refused, not clamped.
constexpr float kMaxEv100 = 64.0f;
// The largest exposure multiplier a scene file or --exposure may give: beyond it the brightest finite radiance
// (fp16's 65504) times the exposure leaves float range in the tone curve, and the frame turns black.
constexpr float kMaxExposure = 1e6f;

// Lagarde and de Rousiers 2014, "Moving Frostbite to Physically Based Rendering", sec. 4.2: the exposure value at
// ISO 100 of f-number N, shutter time t (seconds) and sensitivity S, EV100 = log2(N^2 / t * 100 / S).
double ev100FromCamera(double aperture, double shutterSeconds, double iso);

// Same section: the saturation-based sensor's largest luminance, Lmax = 78 / (0.65 S) N^2 / t = 1.2 * 2^EV100
// cd/m^2, maps to 1, so the image is scaled by 1 / Lmax.
double exposureFromEv100(double ev100);
// Its inverse: the EV100 whose exposure is `exposure` (> 0).
double ev100FromExposure(double exposure);

}  // namespace pbr
