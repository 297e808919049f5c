#pragma once
// The order F6 and Shift+F6 walk the screen's regions in (keyboard_regions.h), as plain
// arithmetic: pure, tested in tests/ui/input/.

#include <optional>
#include <vector>

namespace swarmlab {

/// The region after (direction +1) or before (-1) `current` among those `shown`, wrapping
/// around; from none (the keyboard is in a dialog or the menu bar) the first or the last shown.
/// None when no region is shown.
std::optional<std::size_t> next_region(std::optional<std::size_t> current,
                                       const std::vector<bool>& shown, int direction);

}  // namespace swarmlab
