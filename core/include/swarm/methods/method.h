#pragma once
/// The ways Swarm Lab can move a system forward in time, each described once in one table:
/// the preset validator, the UI's menu, tooltips and plot colours and the method table of
/// docs/physics.md all read it. Adding a method is an enum value, its step function (step_*.cpp), one
/// row in method.cpp and its test.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace swarm {

struct System;

/// analytic: the exact closed-form map of the paper. The others integrate the pairwise
/// force law (eq. 1) numerically, summing over every pair.
enum class Method { analytic, euler, euler_cromer, verlet, rk4 };

/// Everything Swarm Lab knows about one method.
struct MethodInfo {
  Method id;
  std::string_view name;          ///< as written in presets, e.g. "euler-cromer"
  std::string_view display_name;  ///< as shown to people, e.g. "Euler-Cromer"
  int order;                      ///< global order of accuracy in dt; 0 for the exact map
  bool pairwise;                  ///< sums the force over every pair: O(N^2) per step, not O(N)
  void (*step)(System& s, double dt, int threads);  ///< advances an isolated system by dt
  std::string_view description;        ///< one line: what the method does and how it behaves
  std::array<std::uint8_t, 3> colour;  ///< its colour in plots, sRGB 0-255
};

/// Every method, in the order menus and lists show them.
const std::array<MethodInfo, 5>& method_table();
const MethodInfo& info_of(Method m);

std::string_view name_of(Method m);
std::optional<Method> method_named(std::string_view name);

/// The names for a message: "analytic, euler, euler-cromer, verlet or rk4".
std::string method_names_listed();

/// The numerical methods cost O(N^2) per step; the analytic map costs O(N).
bool is_pairwise(Method m);

/// Global order of accuracy in dt (analytic: exact, reported as 0).
int order_of(Method m);

}  // namespace swarm
