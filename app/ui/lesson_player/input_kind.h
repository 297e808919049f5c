#pragma once
// The input the student used last (a finger, the keyboard's navigation, a mouse): lesson words
// for that device ({tap|click|press Space}) on the screen and in what the live region says.

#include "lessons/device_words.h"
#include "ui/state/app_state.h"

namespace swarmlab {

InputKind input_kind(const AppState& state);

}  // namespace swarmlab
