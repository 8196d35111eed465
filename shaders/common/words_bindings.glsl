// Binding points of the word kernels (words_fill.comp, words_copy.comp), which gl::BufferOps
// (src/gl/buffer_ops.cpp) runs; shared by C++ and GLSL. Only #define lines: this file is valid in
// both languages. Each SSBO is bound as a range of at most BufferOps' chunk.
#define WORDS_FILL_TARGET 0  // fill: the words set to uValue
#define WORDS_COPY_SRC 0     // copy: the words read
#define WORDS_COPY_DST 1     // copy: the words written
