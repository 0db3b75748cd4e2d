#!/bin/sh
# Look at an animated SVG of `walker animate` as a person would: render it in a real browser
# (headless Chromium, Debian package `chromium`) and save screenshots.
#
#   scripts/animation-screenshots.sh FILE.svg OUTDIR [T1 T2 ...]
#
# For each moment T (seconds of playback; default 0 0.5 1 2 3) the SVG is pasted into a small
# HTML page whose script pauses the SVG's SMIL clock and sets it to T (the SVG itself has no
# script: the page only seeks it), and Chromium saves OUTDIR/t<T>.png. Two more screenshots show
# the SVG with no script anywhere, as a file (OUTDIR/raw-file.png) and as an <img> in a page,
# the way a README shows it (OUTDIR/raw-img.png); Chromium takes them a moment after the load,
# so a label past "t = 0.0 s" in them means the browser plays the animation by itself. Make an
# SVG first, e.g.
#
#   cargo run --release -p walker-cli -- animate --scene active-level --mu0 0.4 -o walk.svg
#
# CI does not run this script (it needs a browser).
set -eu

if [ $# -lt 2 ]; then
    echo "usage: $0 FILE.svg OUTDIR [T1 T2 ...]" >&2
    exit 2
fi
svg=$1
out=$2
shift 2
[ $# -gt 0 ] || set -- 0 0.5 1 2 3

browser=${CHROMIUM:-/usr/bin/chromium}
if [ ! -x "$browser" ]; then
    echo "no Chromium at $browser: install Debian's package (apt-get install chromium)" >&2
    exit 1
fi
[ -f "$svg" ] || { echo "no file $svg" >&2; exit 2; }
mkdir -p "$out"

# The picture's size from the SVG's root element.
width=$(sed -n 's/.*<svg[^>]* width="\([0-9]*\)".*/\1/p' "$svg" | head -n 1)
height=$(sed -n 's/.*<svg[^>]* height="\([0-9]*\)".*/\1/p' "$svg" | head -n 1)
: "${width:=640}" "${height:=360}"

shot() { # shot OUT.png URL [extra flags]
    png=$1
    url=$2
    shift 2
    "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
        --window-size="$width,$height" --screenshot="$png" "$@" "$url" >/dev/null 2>&1
}

abs_out=$(cd "$out" && pwd)
for t in "$@"; do
    page="$abs_out/t$t.html"
    {
        printf '<!doctype html><html><body style="margin:0">\n'
        cat "$svg"
        printf '<script>const s = document.querySelector("svg"); s.pauseAnimations(); s.setCurrentTime(%s);</script>\n' "$t"
        printf '</body></html>\n'
    } >"$page"
    shot "$abs_out/t$t.png" "file://$page"
    rm -f "$page"
    echo "$out/t$t.png"
done

abs_svg=$(cd "$(dirname "$svg")" && pwd)/$(basename "$svg")
shot "$abs_out/raw-file.png" "file://$abs_svg"
echo "$out/raw-file.png"
printf '<!doctype html><html><body style="margin:0"><img src="file://%s"></body></html>\n' \
    "$abs_svg" >"$abs_out/raw-img.html"
shot "$abs_out/raw-img.png" "file://$abs_out/raw-img.html" --allow-file-access-from-files
rm -f "$abs_out/raw-img.html"
echo "$out/raw-img.png"
