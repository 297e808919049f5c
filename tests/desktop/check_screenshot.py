#!/usr/bin/env python3
"""Checks a Swarm Lab screenshot: the 3D view shows particles and the container, the plot
panel shows the pressure and temperature curves. Standard library only (PNG decoded with zlib).

Usage: check_screenshot.py SHOT.png
       check_screenshot.py --presentation SHOT.png   (presentation mode: light, the view and
                                                      the plots, no controls)
       check_screenshot.py --lesson SHOT.png         (a lesson open: its title and headings in
                                                      the dark theme's lesson colour on the left)
"""
import struct
import sys
import zlib


def read_png(path):
    """Returns (width, height, rows) with rows[y] a bytes object of RGB triples."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in (2, 6) or interlace != 0:
        raise ValueError("expected 8-bit RGB or RGBA, not interlaced")
    channels = 3 if colour_type == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 0xFF
            elif kind == 2:
                line[i] = (line[i] + b) & 0xFF
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 0xFF
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 0xFF
        previous = line
        rows.append(bytes(line) if channels == 3 else bytes(
            v for k, v in enumerate(line) if k % 4 != 3))
    return width, height, rows


def count(rows, x0, x1, y0, y1, test):
    n = 0
    for y in range(y0, y1):
        row = rows[y]
        for x in range(x0, x1):
            r, g, b = row[3 * x], row[3 * x + 1], row[3 * x + 2]
            if test(r, g, b):
                n += 1
    return n


def near(colour, tolerance):
    cr, cg, cb = colour
    return lambda r, g, b: abs(r - cr) <= tolerance and abs(g - cg) <= tolerance and abs(
        b - cb) <= tolerance


def saturated(r, g, b):
    """A lit particle: a strongly coloured pixel (the background and panels are grey-blue)."""
    return max(r, g, b) > 110 and max(r, g, b) - min(r, g, b) > 90


def presentation_checks(width, height, rows):
    """Presentation mode at UI scale 1.5: a light page, the view on the left, the plots on the
    right (about 435 px), no control panel."""
    light = count(rows, 0, width, 0, height, lambda r, g, b: min(r, g, b) > 200)
    view = (20, 780, 120, height - 60)
    plots = (width - 420, width, 60, height)
    coloured = count(rows, *view, lambda r, g, b: max(r, g, b) - min(r, g, b) > 70)
    # The light theme's pressure line (170, 60, 0) and its raw samples (220, 120, 40).
    pressure = count(rows, *plots, lambda r, g, b: r > 140 and r - b > 90 and g < r - 50)
    return [
        ("window is 1280x720", width == 1280 and height == 720, f"{width}x{height}"),
        ("the page is light", light > 0.6 * width * height,
         f"{100 * light / (width * height):.0f} % of pixels light (need > 60 %)"),
        ("particles drawn on the light view", coloured > 1500,
         f"{coloured} coloured pixels (need > 1500)"),
        ("pressure curve in the plots", pressure > 200, f"{pressure} dark orange pixels (need > 200)"),
    ]


def lesson_checks(width, height, rows):
    """A lesson open at 1280x720: the lesson panel on the left shows its title (and, in the
    summary, each task's heading) in the palette's lesson_title colour (255, 217, 115)."""
    title = count(rows, 0, 360, 20, height, near((255, 217, 115), 30))
    coloured = count(rows, 360, 860, 90, height - 60, saturated)
    return [
        ("window is 1280x720", width == 1280 and height == 720, f"{width}x{height}"),
        ("the lesson's title on the left", title > 150,
         f"{title} pixels in the lesson title colour (need > 150)"),
        ("particles beside it", coloured > 200, f"{coloured} coloured pixels in the view (need > 200)"),
    ]


def main():
    mode = sys.argv[1] if len(sys.argv) == 3 else None
    if len(sys.argv) not in (2, 3) or mode not in (None, "--presentation", "--lesson"):
        print(__doc__)
        return 2
    width, height, rows = read_png(sys.argv[-1])
    if mode == "--presentation":
        return report(presentation_checks(width, height, rows))
    if mode == "--lesson":
        return report(lesson_checks(width, height, rows))
    # Layout at 1280x720 and UI scale 1: controls on the left (about 340 px), plots on the
    # right (about 400 px), the 3D view between them.
    view = (360, 860, 90, height - 60)
    plots = (width - 390, width, 60, height)
    checks = [
        ("window is 1280x720", width == 1280 and height == 720, f"{width}x{height}"),
    ]
    particles = count(rows, *view, saturated)
    checks.append(("particles drawn in the 3D view", particles > 3000,
                   f"{particles} strongly coloured pixels (need > 3000)"))
    # The container's outline is pale blue (160, 205, 250) at 90 % opacity over the dark
    # background.
    container = count(rows, *view, near((148, 190, 232), 30))
    checks.append(("container outline drawn", container > 400,
                   f"{container} pale blue pixels (need > 400)"))
    pressure = count(rows, *plots, near((255, 150, 50), 45))
    checks.append(("pressure curve in the plots", pressure > 300,
                   f"{pressure} orange pixels (need > 300)"))
    temperature = count(rows, *plots, near((90, 180, 255), 30))
    checks.append(("temperature curve in the plots", temperature > 300,
                   f"{temperature} light blue pixels (need > 300)"))
    panel = count(rows, 0, 300, 60, height, near((23, 26, 33), 12))
    checks.append(("control panel drawn", panel > 20000, f"{panel} panel pixels (need > 20000)"))
    return report(checks)


def report(checks):
    failed = 0
    for name, ok, detail in checks:
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: {detail}")
        failed += not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
