#pragma once
// Labels that say what the running system is now, not what the preset was when it shipped:
// the title (name, "(edited)", the regime the force and container make), the clock's units,
// and whether a preset opened from text is the shipped one. Pure text, tested without a window.
// The texts are in the language the translator speaks (i18n/translator.h; English unless told,
// as in tests/labels), the clock's numbers with its decimal separator.

#include <string>
#include <vector>

#include "swarm/preset/preset.h"

namespace swarmlab::labels {

/// "attractive (J > 0), isolated", "repulsive (J < 0) in a container", "free (J = 0), ...":
/// the kind of motion the preset's J and container give.
std::string regime_label(const swarm::Preset& preset);

/// The title line: the preset's name (or "(unnamed preset)"), "  (edited)" when edited, and
/// when edited the regime as it is now, so that a swarm made repulsive is not titled
/// "Attractive ..." without a word.
std::string title(const swarm::Preset& preset, bool edited);

/// The clock line for time t of a system of stiffness k = J M (1/time^2) in the preset's
/// container or none: "t = 3.142   ωt/2π = 0.500" only for an isolated attractive system (the
/// one case in which every orbit closes with that period); "t = ...   Ωt = ..." for an
/// isolated repulsive one (its e-foldings); "t = ..." alone once a wall holds the system, where
/// neither number describes the motion.
std::string clock_text(const swarm::Preset& preset, double k, double t);

/// Whether a preset opened from text (a link, a file) differs from the shipped presets: equal
/// to one of them in every field it is the shipped preset; else it is edited, whatever its name.
bool differs_from_shipped(const swarm::Preset& opened, const std::vector<swarm::Preset>& shipped);

}  // namespace swarmlab::labels
