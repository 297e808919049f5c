#include "swarm/method.h"

#include <array>
#include <utility>

namespace swarm {
namespace {

constexpr std::array<std::pair<Method, std::string_view>, 5> kMethodNames{{
    {Method::analytic, "analytic"},
    {Method::euler, "euler"},
    {Method::euler_cromer, "euler-cromer"},
    {Method::verlet, "verlet"},
    {Method::rk4, "rk4"},
}};

}  // namespace

std::string_view name_of(Method m) {
  for (const auto& [method, name] : kMethodNames)
    if (method == m) return name;
  return "?";
}

std::optional<Method> method_named(std::string_view name) {
  for (const auto& [method, n] : kMethodNames)
    if (n == name) return method;
  return std::nullopt;
}

bool is_pairwise(Method m) { return m != Method::analytic; }

int order_of(Method m) {
  switch (m) {
    case Method::analytic:
      return 0;
    case Method::euler:
    case Method::euler_cromer:
      return 1;
    case Method::verlet:
      return 2;
    case Method::rk4:
      return 4;
  }
  return 0;
}

}  // namespace swarm
