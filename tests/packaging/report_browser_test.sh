#!/usr/bin/env bash
# Opens a run's report.html in a real browser (Debian chromium, headless):
# every image of the page must load, and the page must show the figures of
# the run's summary.json. Also renders a screenshot. A copy of the page with
# one broken image reference must be caught (the check can fail).
# Usage: report_browser_test.sh RUN_DIR SCREENSHOT.png
set -euo pipefail
run=$(cd "$1" && pwd) shot=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
[ -s "$run/report.html" ] && [ -s "$run/summary.json" ] || fail "no report.html / summary.json in $run"
profile=$(mktemp -d) && trap 'rm -rf "$profile"' EXIT
chrome() {
  timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --user-data-dir="$profile/$1" "${@:2}" 2> "$profile/$1.log"
}
# After the load event, mark each image loaded or broken (naturalWidth 0).
marker='<script>window.addEventListener("load",function(){var n=0,bad=[];
for(const img of document.images){n++;const ok=img.complete&&img.naturalWidth>0;
img.setAttribute("data-loaded",ok?"yes":"no");if(!ok)bad.push(img.getAttribute("src"));}
var p=document.createElement("pre");p.id="image-check";p.textContent="images="+n+" broken="+bad.length+" "+bad.join(" ");
document.body.appendChild(p);});</script>'
check_page() {  # $1 = page name in $run; prints the image-check line
  local page="$run/$1" dom="$profile/$1.dom"
  chrome "$1" --virtual-time-budget=10000 --dump-dom "file://$page" > "$dom" || fail "chromium on $page"
  grep -o '<pre id="image-check">[^<]*' "$dom" | sed 's/.*>//' || fail "image check did not run on $page"
}
python3 - "$run/report.html" "$marker" <<'PY'
import sys
page, marker = sys.argv[1], sys.argv[2]
html = open(page, encoding="utf-8").read()
assert "</body>" in html
open(page.replace("report.html", "report_check.html"), "w").write(html.replace("</body>", marker + "</body>"))
broken = html.replace('src="map.png"', 'src="missing.png"', 1)
assert broken != html, "map.png not referenced"
open(page.replace("report.html", "report_broken.html"), "w").write(broken.replace("</body>", marker + "</body>"))
PY
result=$(check_page report_check.html)
echo "report.html: $result"
broken=$(check_page report_broken.html)
echo "control with one bad reference: $broken"
rm -f "$run/report_check.html" "$run/report_broken.html"
[[ "$broken" == *"broken=1 missing.png"* ]] || fail "the broken-image control was not caught"
[[ "$result" =~ images=([0-9]+)\ broken=0 ]] && [ "${BASH_REMATCH[1]}" -ge 5 ] || fail "broken or missing images: $result"

# The figures shown are those of summary.json.
cp "$profile/report_check.html.dom" "$profile/dom.html"
python3 - "$profile/dom.html" "$run/summary.json" <<'PY'
import json, re, sys
from html.parser import HTMLParser
dom, summary = open(sys.argv[1], encoding="utf-8").read(), json.load(open(sys.argv[2]))
class Figures(HTMLParser):
    def __init__(self):
        super().__init__(); self.figs = {}; self.key = None; self.depth = 0
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if self.key: self.depth += 1
        elif (a.get("id") or "").startswith("fig-"): self.key, self.depth = a["id"][4:], 1; self.figs[self.key] = ""
    def handle_endtag(self, tag):
        if self.key:
            self.depth -= 1
            if self.depth == 0: self.key = None
    def handle_data(self, data):
        if self.key: self.figs[self.key] += data
p = Figures(); p.feed(dom)
keys = ["input", "pose_method", "entries", "scans", "wall_s", "ms_per_scan", "tiles", "leg_tracks",
        "person_tracks", "sonar_corners"] + (["ate_rmse_m"] if summary["evaluated"] else [])
for k in keys:
    shown, want = p.figs.get(k), summary[k]
    assert shown is not None, f"figure {k} not on the page"
    ok = abs(float(shown) - want) <= 1e-3 * max(1, abs(want)) if isinstance(want, (int, float)) else shown.strip() == want
    assert ok, f"{k}: page shows {shown!r}, summary.json has {want!r}"
    print(f"  {k:14s} page {shown.strip():>12s}  summary.json {want}")
loop = summary["loop_closure"]
assert loop is not None, "the default runs the loop-closure back-end: summary.json has no loop_closure"
for k in ("keyframes", "closures_tested", "closures_accepted", "closures_rejected", "optimizations"):
    shown = p.figs.get(k)
    assert shown is not None and int(shown) == loop[k], f"{k}: page shows {shown!r}, summary.json has {loop[k]!r}"
    print(f"  {k:18s} page {shown.strip():>8s}  summary.json loop_closure.{k} {loop[k]}")
warnings = re.findall(r'<li class="warn">', dom)
assert len(warnings) == len(summary["warnings"]), (len(warnings), summary["warnings"])
for section in ("Loop closure", "Timing per stage", "Effective configuration", "Leg and person tracks", "TBF sonar corners",
                "Evaluation against the reference" if summary["evaluated"] else "Timing"):
    assert section in dom, f"section '{section}' missing"
print(f"  warnings       {len(warnings)} on the page and in summary.json")
PY
mkdir -p "$(dirname "$shot")"
chrome shot --window-size=1280,2200 --hide-scrollbars --screenshot="$shot" "file://$run/report.html" > /dev/null ||
  fail "chromium --screenshot"
[ "$(stat -c %s "$shot")" -gt 20000 ] || fail "screenshot $shot too small"
echo "screenshot: $shot"
echo "PASS"
