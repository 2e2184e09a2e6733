#!/bin/sh
# The HTML page in a real browser: headless Chromium must render it with no
# console message (the page has no scripts, so any message is an SVG or
# HTML error such as a malformed path), and the screenshot must be a
# picture, not a blank page: several colours, among them a saturated one
# that only a drawn series can give.
# Usage: render_html.sh PLOT_SAMPLE SCRATCH_DIR   (from the repository root)
# Exit 77 (skipped) when chromium is not installed.
set -eu
sample=$1 dir=$2
browser=
for b in chromium chromium-browser google-chrome; do
    if command -v "$b" >/dev/null 2>&1; then browser=$b; break; fi
done
[ -n "$browser" ] || { echo "chromium not installed: skipped"; exit 77; }
rm -rf "$dir" && mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
"$sample" "$dir"
# a private profile: no state shared with other runs or the user's browser
timeout 120 "$browser" --headless --no-sandbox --disable-gpu \
    --user-data-dir="$dir/profile" --screenshot="$dir/report.png" \
    --window-size=1200,1600 --enable-logging=stderr --v=0 \
    "file://$dir/report.html" >"$dir/chromium.log" 2>&1 || {
    echo "chromium failed:"; tail -n 20 "$dir/chromium.log"; exit 1; }
if grep -E ':CONSOLE|Uncaught' "$dir/chromium.log" >"$dir/console.log"; then
    echo "console messages while rendering the page:"; cat "$dir/console.log"; exit 1
fi
[ -s "$dir/report.png" ] || { echo "no screenshot written"; exit 1; }
if ! command -v python3 >/dev/null 2>&1; then
    # a blank 1200x1600 page compresses to a few kilobytes
    size=$(wc -c <"$dir/report.png")
    [ "$size" -gt 20000 ] || { echo "screenshot of $size bytes: blank page?"; exit 1; }
    echo "screenshot $size bytes (python3 absent: size check only)"; exit 0
fi
python3 - "$dir/report.png" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, w = 8, b"", 0
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR":
        w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
        assert depth == 8 and ctype in (2, 6), f"unexpected PNG type {depth}/{ctype}"
        bpp = 3 if ctype == 2 else 4
    elif kind == b"IDAT":
        idat += body
    pos += 12 + n
raw = zlib.decompress(idat)
stride = w * bpp
prev = bytearray(stride)
colours, saturated, off = set(), 0, 0
for y in range(h):
    f, line = raw[off], bytearray(raw[off + 1:off + 1 + stride])
    off += 1 + stride
    for i in range(stride):   # undo the PNG row filter
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    prev = line
    for x in range(0, w, 2):
        px = line[x * bpp:x * bpp + 3]
        colours.add(bytes(px))
        saturated += max(px) - min(px) > 100
print(f"{w}x{h} screenshot: {len(colours)} colours, {saturated} saturated pixels sampled")
if len(colours) < 16 or saturated < 50:
    sys.exit("the page looks blank or the figures are missing")
PY
