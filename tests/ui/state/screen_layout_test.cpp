#include "ui/state/screen_layout.h"

#include <doctest/doctest.h>

#include <string>
#include <vector>

using namespace swarmlab;

namespace {

struct Named {
  std::string name;
  ScreenRect rect;
};

std::vector<Named> shown_parts(const ScreenLayout& l) {
  std::vector<Named> parts;
  const Named all[] = {{"view", l.view},         {"transport", l.transport},
                       {"readouts", l.readouts}, {"bottom_strip", l.bottom_strip},
                       {"controls", l.controls}, {"plots", l.plots},
                       {"drawer", l.drawer}};
  for (const Named& n : all)
    if (n.rect.shown()) parts.push_back(n);
  return parts;
}

bool overlap(const ScreenRect& a, const ScreenRect& b) {
  const float eps = 0.01f;  // touching edges are not an overlap
  return a.x + eps < b.right() && b.x + eps < a.right() && a.y + eps < b.bottom() &&
         b.y + eps < a.bottom();
}

/// Every part inside the window below the menu bar, no two overlapping.
void check_fits(const ScreenLayoutInput& in, const ScreenLayout& l) {
  const std::vector<Named> parts = shown_parts(l);
  for (const Named& p : parts) {
    CAPTURE(p.name);
    CHECK(p.rect.x >= -0.01f);
    CHECK(p.rect.y >= in.menu_height - 0.01f);
    CHECK(p.rect.right() <= in.width + 0.01f);
    CHECK(p.rect.bottom() <= in.height + 0.01f);
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      const std::string pair = parts[i].name + " / " + parts[j].name;
      CAPTURE(pair);
      CHECK_FALSE(overlap(parts[i].rect, parts[j].rect));
    }
}

ScreenLayoutInput at(float width, float height, float scale = 1) {
  ScreenLayoutInput in;
  in.width = width, in.height = height;
  in.font = 16 * scale;
  in.menu_height = 23 * scale;
  in.transport_height = 2.8f * in.font;
  in.readouts_height = 8 * in.font;
  return in;
}

}  // namespace

TEST_CASE("screen_layout: the six classroom screens get a layout that fits") {
  struct Screen {
    float width, height;
    LayoutKind kind;
  };
  const Screen screens[] = {{390, 844, LayoutKind::portrait},   {844, 390, LayoutKind::landscape},
                            {1024, 768, LayoutKind::landscape}, {1366, 768, LayoutKind::wide},
                            {1280, 720, LayoutKind::wide},      {1920, 1080, LayoutKind::wide}};
  for (const Screen& s : screens) {
    const ScreenLayoutInput in = at(s.width, s.height);
    const ScreenLayout l = screen_layout(in);
    CAPTURE(s.width);
    CAPTURE(s.height);
    CHECK(l.kind == s.kind);
    check_fits(in, l);
    // The wide layout's side panels keep their full width (22 and 25 lines of text).
    if (s.kind == LayoutKind::wide) {
      CHECK(l.controls.width == doctest::Approx(22 * 16));
      CHECK(l.plots.width == doctest::Approx(25 * 16));
    }
    // The view comes first: at least 40% of the window's width and a third of its height.
    CHECK(l.view.width >= 0.4f * s.width);
    CHECK(l.view.height >= s.height / 3);
    // The transport bar sits right above the view, across its whole width.
    CHECK(l.transport.bottom() == doctest::Approx(l.view.y));
    CHECK(l.transport.width == doctest::Approx(l.view.width));
    // The panels are somewhere: side panels in the wide layout, a drawer in the compact ones.
    if (s.kind == LayoutKind::wide) {
      CHECK(l.controls.shown());
      CHECK(l.plots.shown());
      CHECK(l.readouts.y >= l.view.bottom());
      CHECK_FALSE(l.drawer.shown());
    } else {
      CHECK(l.drawer.shown());
      CHECK(l.drawer.width >= 0.3f * s.width);
      CHECK(l.drawer.height >= 0.3f * (s.height - in.menu_height));
    }
  }
}

TEST_CASE("screen_layout: a large UI scale on a projector keeps the view large") {
  // 1280x720 at UI scale 1.5: the two side panels would leave the view a sliver.
  const ScreenLayoutInput in = at(1280, 720, 1.5f);
  const ScreenLayout l = screen_layout(in);
  CHECK(l.kind == LayoutKind::landscape);
  check_fits(in, l);
  CHECK(l.view.width >= 0.5f * in.width);
  CHECK(l.view.height >= 0.6f * in.height);
}

TEST_CASE("screen_layout: the user's choice overrides the automatic one") {
  ScreenLayoutInput in = at(1920, 1080);
  in.mode = LayoutMode::compact;
  CHECK(screen_layout(in).kind == LayoutKind::landscape);
  check_fits(in, screen_layout(in));
  in = at(390, 844);
  in.mode = LayoutMode::wide;
  const ScreenLayout forced = screen_layout(in);
  CHECK(forced.kind == LayoutKind::wide);
  check_fits(in, forced);
  // Squeezed side panels still leave 40% of the phone's width to the view.
  CHECK(forced.view.width >= 0.4f * in.width - 1);

  LayoutMode mode = LayoutMode::automatic;
  CHECK(parse_layout_mode("compact", mode));
  CHECK(mode == LayoutMode::compact);
  CHECK_FALSE(parse_layout_mode("tiny", mode));
  CHECK(mode == LayoutMode::compact);
}

TEST_CASE("screen_layout: a strip under the view and closed panels") {
  for (LayoutMode mode : {LayoutMode::wide, LayoutMode::compact}) {
    ScreenLayoutInput in = at(1280, 720);
    in.mode = mode;
    in.bottom_strip_height = 60;
    const ScreenLayout l = screen_layout(in);
    CAPTURE(layout_mode_name(mode));
    check_fits(in, l);
    CHECK(l.bottom_strip.height == doctest::Approx(60));
    CHECK(l.bottom_strip.y >= l.view.bottom());
    CHECK(l.bottom_strip.width == doctest::Approx(l.view.width));
  }
  // Both panels closed: the view (with its strips) takes the whole window.
  ScreenLayoutInput in = at(844, 390);
  in.controls = in.plots = false;
  const ScreenLayout l = screen_layout(in);
  check_fits(in, l);
  CHECK_FALSE(l.drawer.shown());
  CHECK(l.view.width == doctest::Approx(844));
  in = at(1920, 1080);
  in.controls = in.plots = false;
  CHECK(screen_layout(in).view.width == doctest::Approx(1920));
}
