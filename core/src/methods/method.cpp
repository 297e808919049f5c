#include "swarm/methods/method.h"

#include "swarm/methods/integrators.h"

namespace swarm {
namespace {

constexpr std::array<MethodInfo, 5> kMethods{{
    {Method::analytic,
     "analytic",
     "Analytic",
     0,
     false,
     step_analytic,
     "every particle on its exact closed-form orbit about the centre of mass (eqs. 7 and 15); "
     "exact for any dt",
     {235, 235, 235}},
    {Method::euler,
     "euler",
     "Euler",
     1,
     true,
     step_euler,
     "x += v dt, then v += a dt from the pairwise forces; the energy grows every step",
     {255, 95, 95}},
    {Method::euler_cromer,
     "euler-cromer",
     "Euler-Cromer",
     1,
     true,
     step_euler_cromer,
     "v += a dt, then x += v dt with the new v; the energy only wobbles and stays bounded",
     {100, 220, 120}},
    {Method::verlet,
     "verlet",
     "Verlet",
     2,
     true,
     step_verlet,
     "velocity Verlet (kick-drift-kick); the energy stays bounded",
     {190, 140, 255}},
    {Method::rk4,
     "rk4",
     "RK4",
     4,
     true,
     step_rk4,
     "classical fourth-order Runge-Kutta; very accurate for small dt, its energy drifts slowly",
     {80, 220, 220}},
}};

}  // namespace

const std::array<MethodInfo, 5>& method_table() { return kMethods; }

const MethodInfo& info_of(Method m) {
  for (const MethodInfo& info : kMethods)
    if (info.id == m) return info;
  return kMethods.front();  // unreachable: every enum value has a row (method_test.cpp)
}

std::string_view name_of(Method m) { return info_of(m).name; }

std::optional<Method> method_named(std::string_view name) {
  for (const MethodInfo& info : kMethods)
    if (info.name == name) return info.id;
  return std::nullopt;
}

std::string method_names_listed() {
  std::string out;
  for (std::size_t i = 0; i < kMethods.size(); ++i) {
    if (i > 0) out += i + 1 == kMethods.size() ? " or " : ", ";
    out += kMethods[i].name;
  }
  return out;
}

bool is_pairwise(Method m) { return info_of(m).pairwise; }

int order_of(Method m) { return info_of(m).order; }

void step(Method m, System& s, double dt, int threads) { info_of(m).step(s, dt, threads); }

}  // namespace swarm
