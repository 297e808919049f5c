#include "report/run_csv.h"

#include <initializer_list>
#include <sstream>

#include "report/csv_field.h"

namespace swarmlab::report {
namespace {

/// A header of plain names ("t,P,T") as quoted fields.
std::string header_row(const std::string& names) {
  std::string out;
  std::istringstream in(names);
  for (std::string name; std::getline(in, name, ',');) out += (out.empty() ? "" : ",") + csv_text(name);
  return out + "\n";
}

std::string number_row(std::initializer_list<double> values) {
  std::string out;
  for (double x : values) out += (out.empty() ? "" : ",") + csv_number(x);
  return out + "\n";
}

}  // namespace

std::string samples_csv(const std::vector<swarm::Sample>& samples) {
  std::string out = header_row(kSamplesCsvHeader);
  for (const swarm::Sample& x : samples)
    out += number_row({x.t, x.P, x.T, x.KE, x.PE, x.E, double(x.hits), x.R, x.books.wall_work,
                       x.books.wall_heat, x.books.drag_loss, x.cm_height, x.size, x.T_kinetic});
  return out;
}

std::string stages_csv(const std::vector<swarm::Stage>& stages) {
  std::string out = header_row(kStagesCsvHeader);
  for (const swarm::Stage& x : stages) out += number_row({x.R, x.V, x.P, x.T, x.E, double(x.hits), x.T_kinetic});
  return out;
}

}  // namespace swarmlab::report
