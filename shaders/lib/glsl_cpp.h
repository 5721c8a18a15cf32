// The subset of GLSL that also compiles as C++ over GLM (render/glsl_cpp.h
// includes the same lib files into a struct whose members are the uniforms),
// so that the CPU glyph path runs the very source the shaders run. Shared
// files write float literals with an f suffix (C++ would take 1.0 as a
// double, and GLM's vector operators take only their own scalar type), use
// constructors instead of swizzles, and declare out parameters with TG_OUT.
// Only preprocessor lines and comments: valid in both languages.
#ifndef TG_GLSL_CPP_H
#define TG_GLSL_CPP_H
#ifdef __cplusplus
#define TG_OUT(T) T&
#else
#define TG_OUT(T) out T
#endif
#endif
