#include "swarm/measure/state_hash.h"

#include <cstring>

namespace swarm {
namespace {

class Fnv1a {
 public:
  void add(std::uint64_t word) {
    // Byte by byte, least significant first, so the hash does not depend on endianness.
    for (int byte = 0; byte < 8; ++byte) {
      hash_ ^= (word >> (8 * byte)) & 0xff;
      hash_ *= 0x100000001b3;  // the 64-bit FNV prime
    }
  }
  void add(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    add(bits);
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325;  // the 64-bit FNV offset basis
};

}  // namespace

std::uint64_t state_hash(const System& s) {
  Fnv1a h;
  h.add(s.J);
  h.add(s.t);
  h.add(std::uint64_t(s.particles.size()));
  for (const Particle& p : s.particles) {
    h.add(p.m);
    for (int d = 0; d < 3; ++d) h.add(p.r[d]);
    for (int d = 0; d < 3; ++d) h.add(p.v[d]);
  }
  return h.value();
}

}  // namespace swarm
