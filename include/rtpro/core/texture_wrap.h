#pragma once
// What an image texture shows outside [0, 1]²: shared by the scene description, the render scene
// and the image layer's texture lookups.
namespace rtpro {

enum class TextureWrap { kRepeat, kClamp, kMirror, kBlack };

}  // namespace rtpro
