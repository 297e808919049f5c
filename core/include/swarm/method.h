#pragma once
/// The ways Swarm Lab can move a system forward in time.

#include <optional>
#include <string_view>

namespace swarm {

/// analytic: the exact closed-form map of the paper. The others integrate the pairwise
/// force law (eq. 1) numerically, summing over every pair.
enum class Method { analytic, euler, euler_cromer, verlet, rk4 };

std::string_view name_of(Method m);
std::optional<Method> method_named(std::string_view name);

/// The numerical methods cost O(N^2) per step; the analytic map costs O(N).
bool is_pairwise(Method m);

/// Global order of accuracy in dt (analytic: exact, reported as 0).
int order_of(Method m);

}  // namespace swarm
