// Binding point of the self-test kernel (fill.comp), which gl::computeSelfTest and tests/gl run;
// shared by C++ and GLSL. Only #define lines: this file is valid in both languages.
#define SELFTEST_OUT 0  // the words fill.comp writes
