#pragma once
// The layers a render can keep beside its colour (AOVs), which the film lays out (film.h) and
// the pixel sums feed (pixel_sums.h).

namespace rtpro {

// kHalves: the mean of the pixel's even-indexed samples and of its odd-indexed ones (two
// independent estimates, half the samples each: from their difference the denoiser bounds its
// noise estimate); kVariance: the sample variance of the pixel's mean colour; kSpp: the samples
// the pixel got (adaptive sampling stops converged pixels early); kMotion: the film motion of
// the camera rays' hits in pixels per frame (FilmMotion, sample_result.h), averaged over the hits.
enum class Aov { kAlbedo, kNormal, kDepth, kObjectId, kHalves, kVariance, kSpp, kMotion };

}  // namespace rtpro
