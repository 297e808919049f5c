#include "swarm/integrators.h"

namespace swarm {

void step(Method m, System& s, double dt, int threads) {
  switch (m) {
    case Method::analytic:
      return step_analytic(s, dt, threads);
    case Method::euler:
      return step_euler(s, dt, threads);
    case Method::euler_cromer:
      return step_euler_cromer(s, dt, threads);
    case Method::verlet:
      return step_verlet(s, dt, threads);
    case Method::rk4:
      return step_rk4(s, dt, threads);
  }
}

}  // namespace swarm
