// vec4s moved as two 64-bit words: lavapipe loads and stores a vector one component per lane at
// a time, so two 64-bit components cost half as much as four floats (the bytes are the same).
// The includer enables GL_EXT_shader_explicit_arithmetic_types_int64.
#ifndef THRONG_WORDS64_GLSL
#define THRONG_WORDS64_GLSL

vec4 fromWords(u64vec2 words) {
  return vec4(uintBitsToFloat(unpackUint2x32(words.x)), uintBitsToFloat(unpackUint2x32(words.y)));
}

u64vec2 toWords(vec4 v) {
  return u64vec2(packUint2x32(floatBitsToUint(v.xy)), packUint2x32(floatBitsToUint(v.zw)));
}

#endif
