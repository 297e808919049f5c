#include "swarm/integrators.h"

namespace swarm {

void step(Method m, System& s, double dt) {
  switch (m) {
    case Method::analytic:
      return step_analytic(s, dt);
    case Method::euler:
      return step_euler(s, dt);
    case Method::euler_cromer:
      return step_euler_cromer(s, dt);
    case Method::verlet:
      return step_verlet(s, dt);
    case Method::rk4:
      return step_rk4(s, dt);
  }
}

}  // namespace swarm
