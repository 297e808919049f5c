#include "report/run_csv.h"

#include <sstream>

namespace swarmlab::report {

std::string samples_csv(const std::vector<swarm::Sample>& samples) {
  std::ostringstream out;
  out.precision(17);
  out << kSamplesCsvHeader << '\n';
  for (const swarm::Sample& x : samples)
    out << x.t << ',' << x.P << ',' << x.T << ',' << x.KE << ',' << x.PE << ',' << x.E << ','
        << x.hits << ',' << x.R << ',' << x.books.wall_work << ',' << x.books.wall_heat << ','
        << x.books.drag_loss << ',' << x.cm_height << ',' << x.size << '\n';
  return out.str();
}

std::string stages_csv(const std::vector<swarm::Stage>& stages) {
  std::ostringstream out;
  out.precision(17);
  out << kStagesCsvHeader << '\n';
  for (const swarm::Stage& x : stages)
    out << x.R << ',' << x.V << ',' << x.P << ',' << x.T << ',' << x.E << ',' << x.hits << '\n';
  return out.str();
}

}  // namespace swarmlab::report
