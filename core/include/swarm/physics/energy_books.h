#pragma once
/// The energy that enters or leaves a system from outside it (walls, a floor, drag), kept
/// apart from the system's own energy so that the books balance:
///   E_end - E0 = wall_work + wall_heat - drag_loss,
/// where E counts every potential (the pair springs and gravity).

namespace swarm {

struct EnergyBooks {
  double wall_work = 0;  ///< done on the particles by moving walls and an inelastic floor
  double wall_heat = 0;  ///< given to the particles by a thermal wall (negative: taken)
  double drag_loss = 0;  ///< taken from the particles by drag, >= 0

  void add(const EnergyBooks& o) {
    wall_work += o.wall_work;
    wall_heat += o.wall_heat;
    drag_loss += o.drag_loss;
  }
  /// What the outside gave the system in all: E_end - E0 when the books balance.
  double net() const { return wall_work + wall_heat - drag_loss; }
};

}  // namespace swarm
