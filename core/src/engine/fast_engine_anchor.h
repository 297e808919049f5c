#pragma once
// The coordinates the fast engine's schedules are made in (anchors) and the margins that keep
// them valid; and the shared motion every particle's lab position adds to its oscillation.
//
// [SECTION] Shared motion: r_i = y_i + o, o = R_cm - Y
// [SECTION] Anchors: coordinates y_i minus a reference path, valid within a margin
// [SECTION] Margins: how wide a new anchor's margin is
// [SECTION] The anchors in use: the current one, older ones still relied on, expiry

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "engine/timing_wheel.h"
#include "swarm/methods/external_forces.h"
#include "swarm/physics/system.h"

namespace swarm::fast {

// [SECTION] Shared motion

/// What every particle's lab position adds to its own oscillation y_i about the origin:
/// r_i = y_i + o with o = R_cm - Y. R_cm moves uniformly, or under gravity g along a parabola,
/// or under drag along ForcedFlow's decaying CM path; Y = sum m_i y_i / M = xc aY + xs bY, xc
/// and xs the flow over the time since the current epoch began.
struct SharedMotion {
  Vec3 R_cm = Vec3::Zero(), V_cm = Vec3::Zero();  ///< at the current time
  Vec3 aY = Vec3::Zero(), bY = Vec3::Zero();
  Vec3 g = Vec3::Zero();  ///< gravity (length/time^2)

  /// o at a time u after the current time: f is the flow at that time and ahead the flow over
  /// u, of which only the CM's part (cm_v, cm_g) is read.
  Vec3 offset_at(const ForcedFlow& f, const ForcedFlow& ahead) const {
    return R_cm + V_cm * ahead.cm_v + ahead.cm_g * g - (f.xc * aY + f.xs * bY);
  }
  /// o' at the current time, f being the flow then.
  Vec3 offset_velocity_at(const ForcedFlow& f) const { return V_cm - (f.vc * aY + f.vs * bY); }
};

// [SECTION] Anchors

/// A choice of coordinates y_i - (xc p + xs q) for the particles' wall windows. Schedules made
/// in it assume that the anchor's offset, o + xc p + xs q, stays within its margin at every
/// step end, so that a particle can reach the wall only where |y_i - (xc p + xs q)| >= R -
/// margin. An anchor takes p, q from Y when it starts, so that its offset then moves only
/// with the CM and the later kicks; re-bases carry p, q over into the new epoch.
///
/// A moving wall spends the same margin: R is the radius the anchor was made for, and at a
/// step end where the wall's radius is R_end the offset must stay within margin - (R - R_end)
/// (margin_at), so that |y_i - (xc p + xs q)| < R - margin still keeps a particle inside R_end.
/// A wall moving out adds to what is left; one moving in eats it, and the anchor expires.
///
/// Under gravity the swarm sits well off the container's centre (|R_cm| 0.1 to 0.5 R), and a
/// margin about the centre would have to hold |R_cm| too, which leaves most windows open. An
/// off-centre anchor is made about a point w (its centre) near its offset: the margin bounds
/// only the offset's drift from w, |offset - w| <= margin, and a particle can reach the wall
/// only where |y_i - (xc p + xs q) + w| >= R - margin (off_centre_window_of). Its p, q also
/// take in a free oscillation that keeps the offset near w while the CM falls (OffsetFit). A
/// centred anchor has w = 0.
struct Anchor {
  std::uint8_t id = 0;                   ///< ids are 8 bits and wrap
  StepIndex start = 0;                   ///< the step in which it became current
  double margin = 0;                     ///< length
  double radius = 0;                     ///< R, the wall's radius it was made for
  double threshold = 0, threshold2 = 0;  ///< T = R - margin and T^2: the windows' radius
  double renew_level = 0;  ///< while current: start a new anchor when the offset passes this
  /// Off-centre: while current, start a new anchor from this step on (its fit's horizon ends).
  StepIndex renew_at = std::numeric_limits<StepIndex>::max();
  /// With a floor: its windows assume that the offset's z stays at least floor_low, so that a
  /// particle can fall through only where its own z is below floor - floor_low; a new anchor
  /// starts when the offset's z drops below floor_renew. -infinity without a floor.
  double floor_low = -std::numeric_limits<double>::infinity();
  double floor_renew = -std::numeric_limits<double>::infinity();
  Vec3 p = Vec3::Zero(), q = Vec3::Zero();
  Vec3 centre = Vec3::Zero();  ///< w: the offset the margin is about

  bool centred() const { return centre == Vec3::Zero(); }
  /// Whether the schedules made in the anchor still hold with this offset at a step end where
  /// the wall's radius is R_end.
  bool holds(const Vec3& offset, double R_end) const {
    const double left = margin_at(R_end);
    return left >= 0 && (offset - centre).squaredNorm() <= left * left &&
           offset.z() >= floor_low;
  }
  /// Whether a current anchor should give way to a new one at this offset and wall radius: a
  /// wall moving out only makes the windows too wide, which costs checks, so a wall's travel
  /// either way counts against renew_level.
  bool wants_renewal(const Vec3& offset, double R_end) const {
    return (offset - centre).norm() + std::abs(radius - R_end) > renew_level ||
           offset.z() < floor_renew;
  }

  /// The anchor's offset o + xc p + xs q at a time u after the current time (f: the flow
  /// then; ahead: the flow over u, as in SharedMotion::offset_at).
  Vec3 offset(const SharedMotion& motion, const ForcedFlow& f, const ForcedFlow& ahead) const {
    return motion.offset_at(f, ahead) + f.xc * p + f.xs * q;
  }
  /// How far the offset may be from w at a step end where the wall's radius is R_end.
  double margin_at(double R_end) const { return margin - (radius - R_end); }
};

// [SECTION] Margins

/// How many particles' largest |y| (J > 0) falls short of the reach R - |R_cm| by between
/// b and b + 1 bins of 0.5 R / kBins: how many a margin of a given width lets near the wall.
struct GapHistogram {
  static constexpr int kBins = 128;
  std::array<std::size_t, kBins> counts{};

  /// The bin of a particle whose largest |y|^2 is max_y2; bins_per_length = kBins / (0.5 R).
  static std::size_t bin_of(double max_y2, double reach, double bins_per_length) {
    // (reach^2 - max |y|^2) / (2 reach) is at most the gap, which errs on the safe side.
    const double gap = (reach * reach - max_y2) / (2 * reach);
    return std::size_t(std::clamp(gap * bins_per_length, 0.0, kBins - 1.0));
  }
};

/// How an off-centre anchor follows the swarm. Its offset moves with the CM (a parabola under
/// gravity and the wall's steady push) and with the free oscillation its reference path leaves
/// (Anchor): choosing that path, F(tau) = xc(tau) A + xs(tau) B less than Y's, makes the offset
/// P(tau) - F(tau), P the CM's predicted path, which the fit keeps close to the constant centre
/// over the horizon (least squares at a few times). residual: the largest distance left there.
struct OffsetFit {
  Vec3 centre = Vec3::Zero();
  Vec3 A = Vec3::Zero(), B = Vec3::Zero();  ///< F and F' when the anchor starts
  double residual = 0;                      ///< length
};

/// The fit for an offset now at `offset`, moving with velocity v and acceleration acc, and a
/// steady push on the CM (the wall's, length/time^2) that kicks Y alike (k = J M >= 0, no
/// drag), over `horizon` (time).
OffsetFit fit_offset_path(const Vec3& offset, const Vec3& v, const Vec3& acc, const Vec3& push,
                          double k, double horizon);

/// The largest OffsetFit::residual an off-centre anchor's margin holds for a wall of radius R
/// (length): anchor_with_margin widens the margin by a multiple of the residual and a slack, up
/// to a cap.
double largest_fit_residual(double R);

/// What a new anchor's margin depends on.
struct MarginInputs {
  double R = 1;          ///< the wall's radius
  double wall_step = 0;  ///< how far a moving wall goes in a step (0 for one that stands)
  double k = 0;          ///< J M
  double omega = 0;      ///< sqrt|k|
  double cm_speed = 0;   ///< |V_cm|
  bool floor = false;    ///< whether the anchor also bounds the offset's z for a floor
  bool off_centre = false;  ///< whether the anchor is made about its offset (Anchor)
  double residual = 0;      ///< off-centre: OffsetFit::residual
  std::size_t particles = 0;
  const GapHistogram* gaps = nullptr;  ///< J > 0: from the last epoch's start
};

/// An anchor whose offset is `offset` now. Its margin covers that (an off-centre anchor is
/// made about it instead: its centre), the drift of the CM over a
/// few time units, a moving wall's travel over a few hundred steps, and, when few particles can
/// come near the wall (the attractive expansion's later stages), as much more as leaves at most
/// N / 100 of them within reach: a wide margin then costs little and lets the anchor live long.
/// With a floor, the offset's z may sink by as much as the margin's width beyond |offset|.
Anchor anchor_with_margin(Anchor anchor, const Vec3& offset, const MarginInputs& in);

// [SECTION] The anchors in use

/// The current anchor, the older ones that particles still rely on, and which anchor each
/// particle's window was made in. A particle keeps its window, and the anchor it relies on,
/// until its next hit or until that anchor expires. Counts are kept per lane, so that the
/// lanes of the engine can move their particles to the current anchor at the same time.
class Anchors {
 public:
  /// Beyond this many old anchors, the oldest is expired.
  static constexpr std::size_t kMaxOld = 64;

  Anchors(std::size_t particles, std::size_t lanes) : anchor_of_(particles, 0), relying_(lanes) {}

  const Anchor& current() const { return current_; }
  std::vector<Anchor>& old() { return old_; }
  /// The id the next anchor gets.
  std::uint8_t next_id() { return next_id_++; }
  /// Keeps the current anchor as an old one, for the particles that rely on it.
  void retire_current() { old_.push_back(current_); }
  /// Makes `next` current (without keeping the previous one: retire_current() does).
  void make_current(const Anchor& next) { current_ = next; }

  bool relies_on_current(std::uint32_t i) const { return anchor_of_[i] == current_.id; }
  /// The first particle from `begin` on, before `end`, that relies on anchor id, or `end`: a
  /// search of bytes (memchr), since the fireball expires an anchor every few steps.
  std::size_t next_relying(std::uint8_t id, std::size_t begin, std::size_t end) const {
    const void* found = std::memchr(anchor_of_.data() + begin, id, end - begin);
    return found ? std::size_t(static_cast<const std::uint8_t*>(found) - anchor_of_.data()) : end;
  }
  /// Particle i (of lane `lane`) relies on the current anchor from now on.
  void move_to_current(std::uint32_t i, int lane) {
    auto& relying = relying_[std::size_t(lane)].count;
    --relying[anchor_of_[i]];
    ++relying[current_.id];
    anchor_of_[i] = current_.id;
  }
  /// Every particle relies on the current anchor, and no old one is kept.
  /// lane_sizes: how many particles each lane has.
  void move_all_to_current(const std::vector<std::size_t>& lane_sizes);

  /// Drops the old anchors no particle relies on any more, and expires those whose offset
  /// leaves their margin at the step's end (f1: the flow then; step: the flow over the step;
  /// R_end: the wall's radius then), and the oldest beyond kMaxOld: expire(id) must reschedule
  /// the particles relying on anchor id.
  template <class Expire>
  void drop_expired(const SharedMotion& motion, const ForcedFlow& f1, const ForcedFlow& step,
                    double R_end,
                    Expire expire) {
    for (std::size_t j = 0; j < old_.size();) {
      const Anchor& a = old_[j];
      std::int64_t relying = 0;
      for (const Relying& lane : relying_) relying += lane.count[a.id];
      const bool too_many = j == 0 && old_.size() > kMaxOld;
      if (relying == 0 || too_many || !a.holds(a.offset(motion, f1, step), R_end)) {
        if (relying > 0) expire(a.id);
        old_.erase(old_.begin() + long(j));
      } else {
        ++j;
      }
    }
  }

 private:
  // One cache line apart: each lane's thread writes its own counts.
  struct alignas(64) Relying {
    std::array<std::int32_t, 256> count{};
  };

  Anchor current_;
  std::vector<Anchor> old_;
  std::uint8_t next_id_ = 0;
  std::vector<std::uint8_t> anchor_of_;  // scanned on expiry
  std::vector<Relying> relying_;         // per lane: how many particles rely on each anchor
};

}  // namespace swarm::fast
