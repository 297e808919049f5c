#pragma once
/// Words that fit the student's device in lesson text: "{tap|click}" reads "tap" to a student
/// whose last input was a finger and "click" to one with a mouse; "{tap *Play*|click *Play*|
/// press *Space*}" adds what a student working from the keyboard is to do. The lesson panel
/// renders each choice for the input in use (docs/lessons.md, "Words for every device").

#include <string>
#include <string_view>

namespace swarmlab {

/// The input the student used last.
enum class InputKind { touch, mouse, keyboard };

/// The text with every {touch|mouse} or {touch|mouse|keyboard} choice replaced by the words for
/// `input` (a two-way choice gives the keyboard the mouse's words). Text without braces is
/// returned as it is.
std::string device_words(std::string_view text, InputKind input);

/// "" when every brace in the text opens a valid choice, else the rule it breaks: a choice
/// holds 2 or 3 non-empty alternatives split by '|', and is closed on its line with no brace
/// inside.
std::string device_words_problem(std::string_view text);

}  // namespace swarmlab
