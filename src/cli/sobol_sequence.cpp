#include "sobol_sequence.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace cosmems::internal {
namespace {

// Joe & Kuo's table for dimensions 2 to 16: the primitive polynomial's degree s, its inner
// coefficients a, and the initial direction numbers m_1..m_s.
struct Primitive {
  int s;
  std::uint32_t a;
  std::array<std::uint32_t, 6> m;
};
constexpr std::array<Primitive, SobolSequence::kMaxDimensions - 1> kTable = {{
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}},
    {5, 13, {1, 1, 1, 3, 11}},
    {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}},
    {6, 13, {1, 1, 1, 15, 21, 21}},
    {6, 16, {1, 3, 1, 13, 27, 49}},
}};

constexpr int kBits = 32;

}  // namespace

SobolSequence::SobolSequence(int dimensions) {
  if (dimensions < 1 || dimensions > kMaxDimensions) {
    throw std::invalid_argument("a Sobol sequence of " + std::to_string(dimensions) +
                                " dimensions: this one has 1 to " + std::to_string(kMaxDimensions));
  }
  directions_.assign(dimensions, std::vector<std::uint32_t>(kBits));
  // Dimension 1 is van der Corput's: m_k = 1 for every k.
  for (int k = 0; k < kBits; ++k) directions_[0][k] = 1u << (kBits - 1 - k);
  for (int j = 1; j < dimensions; ++j) {
    const Primitive& p = kTable[j - 1];
    std::vector<std::uint32_t>& v = directions_[j];
    for (int k = 0; k < p.s; ++k) v[k] = p.m[k] << (kBits - 1 - k);
    // v_k = v_(k-s) ^ (v_(k-s) >> s) ^ sum over the polynomial's inner terms a_i v_(k-i).
    for (int k = p.s; k < kBits; ++k) {
      std::uint32_t next = v[k - p.s] ^ (v[k - p.s] >> p.s);
      for (int i = 1; i < p.s; ++i) {
        if ((p.a >> (p.s - 1 - i)) & 1u) next ^= v[k - i];
      }
      v[k] = next;
    }
  }
}

double SobolSequence::Coordinate(std::uint64_t index, int j, std::uint32_t shift) const {
  std::uint32_t x = 0;
  const std::vector<std::uint32_t>& v = directions_[j];
  // The Gray code of the index selects the direction numbers XORed together.
  const std::uint64_t gray = index ^ (index >> 1);
  for (int k = 0; k < kBits && (gray >> k) != 0; ++k) {
    if ((gray >> k) & 1u) x ^= v[k];
  }
  return static_cast<double>(x ^ shift) * 0x1p-32;
}

}  // namespace cosmems::internal
