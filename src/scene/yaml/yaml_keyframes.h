#pragma once
// Animated values: any number or list of numbers in a scene may be written as
//   {keyframes: {1: [0, 1, 6], 120: [4, 1, 2]}, interpolation: linear}
// and becomes its value at the frame being rendered (the scene variable `frame`, set by
// --frames for each frame or by -D frame=N, 1 when unset). Before the first key the first value
// holds, after the last the last. interpolation: linear (default), smooth (ease in and out
// between keys: smoothstep) or step (the last key at or before the frame).
#include "yaml_document.h"

namespace rtpro {

bool is_keyframed(const YamlNode& node);

// The value of the keyframed `animated` at `frame`, positioned at `animated`. Throws InputError
// at the offending node for keys that are not frame numbers, values of different shapes, or an
// unknown interpolation. The value's nodes are made in `arena`.
YamlNodePtr value_at_frame(const YamlNode& animated, double frame, YamlNodeArena& arena);

}  // namespace rtpro
