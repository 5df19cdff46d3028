// The cosine of two unit vectors, for the word vectors (vectors/) and the
// preference model that compares things by them (knowledge/).
#pragma once

#include <span>

namespace apprentice {

// The dot product of two unit vectors; 0 when either is empty or their
// sizes differ.
double cosine(std::span<const float> a, std::span<const float> b);

}  // namespace apprentice
