#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `ifsfx studio`'s server on the real binary (docs/studio.md): the token, Host and Origin checks,
# bad requests answered with a 4xx and the server still up, a render's PNG equal to `ifsfx render`
# of the same preset and options byte for byte (a colouring IFS too, as --colouring), the raw RGBA
# pictures equal to the PNG's pixels, the output policy of save, the folder's presets and
# Fractint entries (unusable ones with their reason), sources, uploads, a newer render cancelling
# the one in flight of the same tab only, and SIGINT/SIGTERM stopping it within
# IFSFX_STOP_BOUND_MS (default 500) with exit 130/143 and no temporary file left, also with a
# connection held open (HTTP keep-alive); a relative --source found in --folder.
# Usage: studio_server_test.sh IFSFX WORKDIR
set -uo pipefail
# shellcheck source=studio_start.sh
source "$(dirname "$0")/studio_start.sh"
ifsfx=$1
work=$2
bound_ms=${IFSFX_STOP_BOUND_MS:-500}
web=$(cd "$(dirname "$0")/../../studio/web" && pwd)
png_tool="$(cd "$(dirname "$0")" && pwd)/studio_png.py"
rm -rf "$work" && mkdir -p "$work/folder" "$work/tmp"
cd "$work" || exit 1
command -v curl >/dev/null || { echo "SKIP: curl is missing"; exit 77; }
# Debian's python3 (a version manager's shim in PATH can take a second to start)
py=$(command -v /usr/bin/python3 || command -v python3) || { echo "SKIP: python3 is missing"; exit 77; }
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok: $*"; }

pid=

# code METHOD PATH [curl args...]: the HTTP status (the body in $work/body, headers in
# $work/headers)
code() {
  local method=$1 path=$2
  shift 2
  curl -s -o "$work/body" -D "$work/headers" -w '%{http_code}' -X "$method" "$@" "$base$path"
}
header() { sed -n "s/^$1: //Ip" "$work/headers" | tr -d '\r'; }
# expect STATUS WHAT METHOD PATH [curl args...]: the status, and a JSON error for a 4xx
expect() {
  local want=$1 what=$2
  shift 2
  local c
  c=$(code "$@")
  if [[ $c != "$want" ]]; then
    fail "$what: $c, expected $want ($(head -c 300 "$work/body" | tr -d '\0'))"
  elif [[ $want == 4* ]] && ! grep -q '"error"' "$work/body"; then
    fail "$what: $c without a JSON error"
  else
    pass "$what: $c$([[ $want == 4* ]] && echo " ($(head -c 200 "$work/body"))")"
  fi
}
json() { "$py" -c "import json, sys; d = json.load(open('$work/body')); print($1)"; }

stop_check() {  # stop_check SIGNAL EXPECTED_EXIT
  local signal=$1 expected=$2
  local t0 t1 rc
  t0=$(date +%s%N)
  kill -s "$signal" "$pid"
  wait "$pid"
  rc=$?
  t1=$(date +%s%N)
  local ms=$(((t1 - t0) / 1000000))
  [[ $rc == "$expected" ]] && pass "$signal: exit $rc" || fail "$signal: exit $rc, expected $expected"
  ((ms <= bound_ms)) && pass "$signal: stopped in $ms ms" || fail "$signal: stopped in $ms ms (> $bound_ms)"
  [[ -z $(ls -A "$work/tmp") ]] && pass "$signal: no temporary file left" ||
    fail "$signal: left $(ls -A "$work/tmp")"
  [[ -z $(find "$work/folder" -name '.*') ]] || fail "$signal: hidden files left in the folder"
}

start_studio barnsley-fern
[[ $url == http://127.0.0.1:* ]] && pass "listens on 127.0.0.1" || fail "URL $url"
ss -ltn 2>/dev/null | grep -q "127.0.0.1:$port " && pass "bound to loopback only" || true

# The token
c=$(code GET /api/presets); [[ $c == 403 ]] && pass "no token: 403" || fail "no token: $c"
grep -q '"error"' "$work/body" || fail "no token: no JSON error ($(cat "$work/body"))"
c=$(code GET /api/presets -H "X-Ifsfx-Token: 0123"); [[ $c == 403 ]] && pass "wrong token: 403" || fail "wrong token: $c"
c=$(code GET /api/presets "${auth[@]}"); [[ $c == 200 ]] && pass "token: 200" || fail "token: $c"
grep -q '"barnsley-fern"' "$work/body" || fail "presets: no barnsley-fern"
c=$(code GET /api/presets -H "Cookie: ifsfx_token=$token"); [[ $c == 200 ]] && pass "cookie: 200" || fail "cookie: $c"

# Host and Origin (DNS rebinding, cross-site requests)
c=$(code GET /api/presets "${auth[@]}" -H "Host: evil.example:$port"); [[ $c == 403 ]] && pass "bad Host: 403" || fail "bad Host: $c"
c=$(code GET / -H "Host: evil.example"); [[ $c == 403 ]] && pass "bad Host on the page: 403" || fail "bad Host on the page: $c"
c=$(code GET /api/presets "${auth[@]}" -H "Host: localhost:$port"); [[ $c == 200 ]] && pass "Host localhost: 200" || fail "Host localhost: $c"
c=$(code GET /api/presets "${auth[@]}" -H "Host: 192.0.2.7:$port"); [[ $c == 403 ]] && pass "another address as Host, loopback only: 403" || fail "another address as Host: $c"
c=$(code GET /api/presets "${auth[@]}" -H "Host: localhost:1"); [[ $c == 403 ]] && pass "another port in Host: 403" || fail "another port in Host: $c"
c=$(code POST /api/render "${auth[@]}" -H "Origin: http://evil.example" --data '{}'); [[ $c == 403 ]] && pass "bad Origin: 403" || fail "bad Origin: $c"

# The page and its files
c=$(code GET "/?token=$token"); [[ $c == 200 ]] && grep -q 'studio.js' "$work/body" && pass "page: 200" || fail "page: $c"
! grep -Eq 'https?://' "$work/body" && pass "page: no external URL" || fail "page: names an external URL"

# Bad requests: 4xx with a JSON error, and the server still answers
c=$(code POST /api/render "${auth[@]}" --data '{"maps": [[0.5, 0, 0, 0.5'); [[ $c == 400 ]] && pass "malformed JSON: 400" || fail "malformed JSON: $c"
grep -q '"error"' "$work/body" || fail "malformed JSON: no JSON error"
c=$(code POST /api/render "${auth[@]}" --data '{"maps": [[2, 0, 0, 2, 0, 0]]}'); [[ $c == 400 ]] && pass "expansive IFS: 400 ($(cat "$work/body"))" || fail "expansive IFS: $c"
c=$(code POST /api/render "${auth[@]}" --data '{"maps": [[0.5, 0, 0, 0.5, 0, 0]], "size": "0x5"}'); [[ $c == 400 ]] && pass "bad size: 400" || fail "bad size: $c"
head -c 2000000 /dev/zero | tr '\0' ' ' >"$work/big.json"
c=$(code POST /api/render "${auth[@]}" -H 'Content-Type: application/json' --data-binary "@$work/big.json"); [[ $c == 413 ]] && pass "2 MB body: 413" || fail "2 MB body: $c"
c=$(code GET /api/nothing "${auth[@]}"); [[ $c == 404 ]] && pass "unknown path: 404" || fail "unknown path: $c"
c=$(code GET "/api/preset?name=/etc/passwd" "${auth[@]}"); [[ $c == 404 ]] && pass "preset by path: 404" || fail "preset by path: $c"
c=$(code GET /api/presets "${auth[@]}"); [[ $c == 200 ]] && pass "still answers" || fail "server gone after bad requests: $c"

# Same pixels as `ifsfx render`: the preset saved by the studio, rendered by the command line
code GET "/api/preset?name=barnsley-fern" "${auth[@]}" >/dev/null
preset=$(cat "$work/body")
c=$(code POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"fern.toml\",}")
[[ $c == 200 && -f folder/fern.toml ]] && pass "save: fern.toml" || fail "save: $c $(cat "$work/body")"
cp "$web/sample.png" folder/photo.png
for args in "tops 256x256" "attractor 200x160" "steal 256x256 sample" "steal 128x96 photo.png"; do
  read -r mode size source <<<"$args"
  extra=""; cli=()
  if [[ $mode == steal ]]; then
    extra="\"source\": \"$source\","
    cli=(--source "$web/sample.png")
    [[ $source == sample ]] || cli=(--source "folder/$source")
  fi
  c=$(code POST /api/render "${auth[@]}" \
    --data "${preset/#\{/\{$extra \"mode\": \"$mode\", \"size\": \"$size\",}")
  cp "$work/body" "$work/studio-$mode.png"
  "$ifsfx" render folder/fern.toml --mode "$mode" --size "$size" "${cli[@]}" -q -o "$work/cli-$mode.png"
  [[ $c == 200 ]] && cmp -s "$work/studio-$mode.png" "$work/cli-$mode.png" &&
    pass "$mode $size $source: the studio's PNG is ifsfx render's, byte for byte" ||
    fail "$mode $size: $c, PNGs differ ($(head -c 200 "$work/body" | tr -d '\0'))"
done

# The output policy of save: plain names in --folder, never over an input
c=$(code POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"../out.toml\",}"); [[ $c == 400 && ! -e out.toml ]] && pass "save ../out.toml: 400" || fail "save ../out.toml: $c"
c=$(code POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"fern.png\",}"); [[ $c == 400 ]] && pass "save fern.png: 400" || fail "save fern.png: $c"
c=$(code POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"mode\": \"steal\", \"source\": \"../x.png\",}"); [[ $c == 400 ]] && pass "source ../x.png: 400" || fail "source ../x.png: $c"
ln -s /etc/hostname folder/link.png
c=$(code POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"mode\": \"steal\", \"source\": \"link.png\",}"); [[ $c == 400 ]] && pass "source leading out of the folder: 400" || fail "source leading out of the folder: $c"
rm folder/link.png

# ---- The editor's endpoints ----

# The page's modules: plain names of the web folder only
expect 200 "live.js" GET /live.js
[[ $(header Content-Type) == text/javascript* ]] || fail "live.js: Content-Type $(header Content-Type)"
expect 404 "a module that is not there" GET /nothing.js
expect 404 "a path out of the web folder" GET /..%2Fstudio_command.cpp

# Defaults for N maps: the palette and the colouring tiling
expect 200 "defaults for 4 maps" GET "/api/defaults?maps=4" "${auth[@]}"
[[ $(json "len(d['colours']), len(d['colouring']), d['colouring'][0]") == "4 4 [0.5, 0.0, 0.0, 0.5, 0.0, 0.0]" ]] &&
  pass "defaults: 4 colours and the quadrant tiling" || fail "defaults: $(cat "$work/body")"
for n in 0 65 x; do expect 400 "defaults for maps=$n" GET "/api/defaults?maps=$n" "${auth[@]}"; done

# The tab's id: a newer render cancels the render in flight of the same tab only
expect 400 "a malformed X-Ifsfx-Client" POST /api/render "${auth[@]}" -H 'X-Ifsfx-Client: a/b' --data "$preset"
long="${preset/#\{/\{\"mode\": \"measure\", \"size\": \"2048x2048\", \"quality\": 4000,}"
curl -s -o /dev/null -w '%{http_code}' "${auth[@]}" -H 'X-Ifsfx-Client: tab1' -X POST "$base/api/render" --data "$long" >"$work/first" &
first=$!
sleep 0.5
c=$(code POST /api/render "${auth[@]}" -H 'X-Ifsfx-Client: tab2' --data "${preset/#\{/\{\"size\": \"64x64\",}")
sleep 0.2
[[ $c == 200 ]] && kill -0 $first 2>/dev/null && pass "another tab's render leaves this tab's running" ||
  fail "two tabs: the second answered $c, the first $(kill -0 $first 2>/dev/null && echo runs || cat "$work/first")"
c=$(code POST /api/render "${auth[@]}" -H 'X-Ifsfx-Client: tab1' --data "${preset/#\{/\{\"size\": \"64x64\",}")
wait $first
[[ $(cat "$work/first") == 409 && $c == 200 ]] && pass "the same tab's newer render cancels it (409, then 200)" ||
  fail "same tab: first $(cat "$work/first"), second $c"

# Raw RGBA: the PNG's pixels, with the size and the view in headers
for args in "tops 96x80" "measure 64x64" "attractor 50x40" "steal 72x72"; do
  read -r mode size <<<"$args"
  body="${preset/#\{/\{\"mode\": \"$mode\", \"size\": \"$size\",}"
  code POST /api/render "${auth[@]}" --data "$body" >/dev/null && cp "$work/body" "$work/$mode.png"
  view_png=$(header X-Ifsfx-View)
  c=$(code POST /api/render "${auth[@]}" --data "${body/#\{/\{\"format\": \"rgba\",}")
  [[ $c == 200 && $(header X-Ifsfx-Size) == "$size" && $(header X-Ifsfx-View) == "$view_png" ]] ||
    fail "rgba $mode: $c, size $(header X-Ifsfx-Size), view $(header X-Ifsfx-View)"
  "$py" "$png_tool" same-pixels "$work/$mode.png" "$work/body" "${size%x*}" "${size#*x}" &&
    pass "rgba $mode $size: the PNG's pixels" || fail "rgba $mode $size: not the PNG's pixels"
done
for h in X-Ifsfx-Render-Ms X-Ifsfx-Encode-Ms X-Ifsfx-Request-Ms; do
  [[ $(header $h) =~ ^[0-9.]+$ ]] || fail "render: no $h header"
done
expect 400 "format jpeg" POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"format\": \"jpeg\",}"

# The colouring IFS: as `ifsfx render --colouring` of the TOML save writes beside the preset
swap='[[0.5, 0, 0, 0.5, 0.5, 0.5], [0.5, 0, 0, 0.5, 0, 0.5], [0.5, 0, 0, 0.5, 0.5, 0], [0.25, 0, 0, 0.5, 0, 0]]'
c=$(code POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"swap.toml\", \"colouring\": $swap,}")
[[ $c == 200 && -f folder/swap.toml && -f folder/swap.colouring.toml && $(json "d['colouring']") == swap.colouring.toml ]] &&
  pass "save with a colouring: swap.toml and swap.colouring.toml" || fail "save with a colouring: $c $(cat "$work/body")"
c=$(code POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"mode\": \"steal\", \"size\": \"128x128\", \"colouring\": $swap,}")
cp "$work/body" "$work/studio-swap.png"
fitted=$(header X-Ifsfx-Colouring)
"$ifsfx" render folder/swap.toml --mode steal --size 128x128 --source "$web/sample.png" --colouring folder/swap.colouring.toml -q -o "$work/cli-swap.png"
[[ $c == 200 ]] && cmp -s "$work/studio-swap.png" "$work/cli-swap.png" &&
  pass "steal with a colouring: ifsfx render --colouring's PNG, byte for byte" || fail "steal with a colouring: $c, PNGs differ"
# The attractor of swap is the unit square: fitting it changes it by rounding only.
[[ $("$py" -c "import json; print([[round(x, 9) + 0 for x in m] for m in json.loads('$fitted')])") == \
   "[[0.5, 0.0, 0.0, 0.5, 0.5, 0.5], [0.5, 0.0, 0.0, 0.5, 0.0, 0.5], [0.5, 0.0, 0.0, 0.5, 0.5, 0.0], [0.25, 0.0, 0.0, 0.5, 0.0, 0.0]]" ]] &&
  pass "X-Ifsfx-Colouring: the colouring as used" || fail "X-Ifsfx-Colouring: $fitted"
cmp -s "$work/studio-swap.png" "$work/studio-steal.png" && fail "the colouring changes nothing"
expect 400 "a colouring of 2 maps for 4" POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"mode\": \"steal\", \"colouring\": [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 0.5, 0]],}"
expect 400 "a colouring that is no list of maps" POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"mode\": \"steal\", \"colouring\": 3,}"
expect 400 "save with a colouring of 1 map" POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"one.toml\", \"colouring\": [[0.5, 0, 0, 0.5, 0, 0]],}"
[[ ! -e folder/one.toml && ! -e folder/one.colouring.toml ]] && pass "a refused save writes neither file" || fail "a refused save left files"

# The folder's presets: .toml files and Fractint entries, the unusable ones with their reason
cat >folder/mixed.ifs <<'IFS'
; entries for the studio's tests
fern { ; Barnsley's fern
  0 0 0 .16 0 0 .01
  .85 .04 -.04 .85 0 1.6 .85
  .2 -.26 .23 .22 0 1.6 .07
  -.15 .28 .26 .24 0 .44 .07
}
cube (3D) {
  .5 0 0 0 .5 0 0 0 .5 0 0 0 .5
}
flipper { ; contracts on average only
  -1 0 0 1 0 0 .5
  .25 0 0 .25 0 0 .5
}
grower {
  2 0 0 2 0 0 .5
  1.5 0 0 1.5 1 1 .5
}
IFS
printf 'name = "broken"\nmaps = [[0.5, 0, 0]]\n' >folder/broken.toml
printf 'name = "x"\n' >folder/texture.super.toml
expect 200 "the folder's presets" GET /api/folder "${auth[@]}"
listing=$(json "'; '.join(r['file'] + ':' + r.get('entry', '-') + ':' + ('ok' if not r['problem'] else r['problem'].replace('$work/folder/', '')[:32]) for r in d)")
expected="broken.toml:-:broken.toml:2: map 1: needs 6 nu; fern.toml:-:ok; mixed.ifs:fern:ok; mixed.ifs:cube:mixed.ifs:8: entry 'cube': only ; mixed.ifs:flipper:ok; mixed.ifs:grower:mixed.ifs:grower: the IFS must c; swap.colouring.toml:-:ok; swap.toml:-:ok"
[[ $listing == "$expected" ]] && pass "folder listing, the unusable with their reason" || fail "folder listing: $listing"
expect 200 "a Fractint entry" GET "/api/preset?file=mixed.ifs&entry=fern" "${auth[@]}"
[[ $(json "d['name'], len(d['maps']), d['allow_expansive']") == "fern 4 False" ]] || fail "fern entry: $(cat "$work/body")"
expect 200 "an entry that contracts on average" GET "/api/preset?file=mixed.ifs&entry=flipper" "${auth[@]}"
[[ $(json "d['allow_expansive'], len(d['warnings'])") == "True 1" ]] && pass "flipper: allow_expansive and a warning" || fail "flipper: $(cat "$work/body")"
flipper=$(cat "$work/body")
expect 200 "render the flipper entry" POST /api/render "${auth[@]}" --data "${flipper/#\{/\{\"size\": \"64x64\",}"
expect 200 "save the flipper entry" POST /api/save "${auth[@]}" --data "${flipper/#\{/\{\"file\": \"flipper.toml\",}"
"$ifsfx" render folder/flipper.toml --size 32x32 -q -o "$work/flipper.png" && pass "ifsfx render loads the saved flipper.toml" || fail "ifsfx render refuses the saved flipper.toml"
expect 400 "a (3D) entry" GET "/api/preset?file=mixed.ifs&entry=cube" "${auth[@]}"
expect 400 "an entry that does not contract" GET "/api/preset?file=mixed.ifs&entry=grower" "${auth[@]}"
expect 404 "an entry that is not there" GET "/api/preset?file=mixed.ifs&entry=nothing" "${auth[@]}"
expect 400 "a malformed .toml" GET "/api/preset?file=broken.toml" "${auth[@]}"
expect 404 "a missing file" GET "/api/preset?file=missing.toml" "${auth[@]}"
expect 400 "a file that is no preset" GET "/api/preset?file=mixed.txt" "${auth[@]}"
expect 400 "a superIFS file" GET "/api/preset?file=texture.super.toml" "${auth[@]}"
expect 400 "an entry of a .toml" GET "/api/preset?file=fern.toml&entry=x" "${auth[@]}"
expect 400 "a preset out of the folder" GET "/api/preset?file=..%2Ffern.toml" "${auth[@]}"
expect 200 "swap.toml with its colouring" GET "/api/preset?file=swap.toml" "${auth[@]}"
[[ $(json "d['origin_colouring'], d['colouring'][3]") == "swap.colouring.toml [0.25, 0.0, 0.0, 0.5, 0.0, 0.0]" ]] &&
  pass "a folder preset brings NAME.colouring.toml" || fail "swap.toml: $(cat "$work/body")"
expect 400 "save over a preset opened from the folder" POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"swap.toml\",}"

# ---- Flames: a flame of the folder opened, rendered, edited and saved (docs/studio.md, "Flames") ----
# A flame's document is larger than cpp-httplib takes as a form (8 KiB): sent as JSON, as the page does.
jsonh=(-H 'Content-Type: application/json')
palette=$("$py" -c "print(''.join('%02X%02X%02X' % (k, 255 - k, (4 * k) % 256) for k in range(256)))")
cat >folder/pair.flame <<XML
<flames>
<flame name="spiral" size="96 72" center="0.1 -0.2" scale="30" quality="40" oversample="1"
  filter="0.5" brightness="4" gamma="2.5" background="0 0 0">
 <xform weight="0.6" color="0" linear="0.5" julian="0.5" julian_power="3" julian_dist="1"
  coefs="0.6 0.2 -0.2 0.6 0.3 -0.1"/>
 <xform weight="0.4" color="1" color_speed="0.3" spherical="1" coefs="0.5 -0.3 0.3 0.5 -0.4 0.2"
  post="1 0 0 1 0.1 0"/>
 <finalxform color="0.5" linear="1" coefs="1.1 0 0 1.1 0 0"/>
 <palette count="256" format="RGB">$palette</palette>
</flame>
<flame name="turned" size="80 60" center="0 0" scale="24" rotate="30" quality="40" palette="15" hue="0.2">
 <xform weight="1" color="0" linear="1" coefs="0.5 0 0 0.5 0.5 0"/>
 <xform weight="1" color="1" swirl="1" coefs="0.5 0 0 0.5 -0.5 0.3"/>
</flame>
<flame><xform weight="1" nope="1" coefs="0.5 0 0 0.5 0 0"/><palette count="256" format="RGB">$palette</palette></flame>
</flames>
XML
expect 200 "the folder with a flame file" GET /api/folder "${auth[@]}"
listing=$(json "'; '.join(r['file'] + ':' + r['entry'] + ':' + str(r['maps']) + ':' + (r['problem'].replace('$work/folder/', '') or 'ok') for r in d if r.get('flame'))")
[[ $listing == 'pair.flame:spiral:2:ok; pair.flame:turned:2:ok; pair.flame:2:0:pair.flame: flame "#2": xform 0: unknown variation "nope"' ]] &&
  pass "each flame of pair.flame listed as FILE:NAME (the unusable with its reason)" || fail "flames listed: $listing"
expect 200 "the variations" GET /api/flame/variations "${auth[@]}"
[[ $(json "[v['params'] for v in d if v['name'] == 'julian'][0]") == "[{'default': 1.0, 'name': 'julian_power'}, {'default': 1.0, 'name': 'julian_dist'}]" ]] &&
  pass "the variations: julian with its parameters" || fail "variations: $(json "[v for v in d if v['name'] == 'julian']")"
expect 200 "a flame of the folder" GET "/api/preset?file=pair.flame&entry=spiral" "${auth[@]}"
cp "$work/body" "$work/spiral.json"
# coefs="a b c d e f" is x' = a·x + c·y + e, y' = b·x + d·y + f in the flame plane (y down): the
# editor's map, y up, is [a, -c, -b, d, e, -f].
[[ $(json "d['maps'][0], d['flame']['xforms'][1]['variations'], d['flame']['final']['coefs'], d['flame']['palette']['colours'][1]") == \
   "[0.6, 0.2, -0.2, 0.6, 0.3, 0.1] [{'name': 'spherical', 'params': {}, 'weight': 1.0}] [1.1, 0.0, 0.0, 1.1, 0.0, 0.0] [0.00392156862745098, 0.996078431372549, 0.01568627450980392, 1.0]" ]] &&
  pass "a flame's document: the editor-plane map, variations, final xform, palette" || fail "spiral: $(head -c 600 "$work/body")"
# flame_pixels DOC SIZE CLI_SPEC WHAT [MODE]: the studio's pixels of DOC (in MODE; steal: from
# photo.png) are `ifsfx render CLI_SPEC [--mode MODE]`'s
flame_pixels() {
  local doc=$1 size=$2 spec=$3 what=$4 mode=${5:-measure} c
  local cli=(--mode "$mode")
  [[ $mode == steal ]] && cli+=(--source folder/photo.png)
  c=$(code POST /api/render "${auth[@]}" "${jsonh[@]}" --data "$("$py" -c "import json; d = json.load(open('$doc')); d.update(size='$size', format='rgba', mode='$mode', source='photo.png'); print(json.dumps(d))")")
  "$ifsfx" render "$spec" "${cli[@]}" --size "$size" -q -o "$work/cli-flame.png" 2>"$work/cli-flame.err" || fail "$what: ifsfx render $spec: $(cat "$work/cli-flame.err")"
  [[ $c == 200 ]] && "$py" "$png_tool" same-pixels "$work/cli-flame.png" "$work/body" "${size%x*}" "${size#*x}" &&
    pass "$what: the studio's pixels are ifsfx render's" || fail "$what: $c, not ifsfx render's pixels ($(head -c 200 "$work/body" | tr -d '\0'))"
}
flame_pixels "$work/spiral.json" 96x72 folder/pair.flame:spiral "spiral"
[[ $(header X-Ifsfx-View) == "-1.5,-1,1.7000000000000002,1.4" ]] &&
  pass "the flame's view: its camera, y up" || fail "the flame's view: $(header X-Ifsfx-View)"
code GET "/api/preset?file=pair.flame&entry=turned" "${auth[@]}" >/dev/null && cp "$work/body" "$work/turned.json"
flame_pixels "$work/turned.json" 80x60 folder/pair.flame:turned "a turned camera and a library palette"
# Its attractor, tops and steal: the xforms through the chaos game, as `ifsfx render --mode` draws them
flame_pixels "$work/spiral.json" 96x72 folder/pair.flame:spiral "spiral in tops mode" tops
flame_pixels "$work/turned.json" 80x60 folder/pair.flame:turned "turned in steal mode from photo.png" steal
flame_pixels "$work/spiral.json" 64x48 folder/pair.flame:spiral "spiral's attractor" attractor
# An edit (a map moved, a variation's weight and parameter), saved, renders as the page showed it
"$py" -c "
import json
d = json.load(open('$work/spiral.json'))
d['maps'][1][4] += 0.25
d['flame']['xforms'][0]['variations'][1]['weight'] = 0.7
d['flame']['xforms'][0]['variations'][1]['params']['julian_power'] = 5
d['flame']['xforms'][1]['variations'].append({'name': 'swirl', 'weight': 0.2})
json.dump(d, open('$work/edited.json', 'w'))
d['file'] = 'edited.flame'
json.dump(d, open('$work/save.json', 'w'))"
expect 200 "save a flame" POST /api/save "${auth[@]}" "${jsonh[@]}" --data "@$work/save.json"
grep -q 'julian="0.7" julian_power="5" julian_dist="1"' folder/edited.flame && grep -q 'swirl="0.2"' folder/edited.flame &&
  pass "edited.flame holds the edits" || fail "edited.flame: $(cat folder/edited.flame | head -5)"
flame_pixels "$work/edited.json" 96x72 folder/edited.flame "the saved flame"
expect 200 "reopen the saved flame" GET "/api/preset?file=edited.flame" "${auth[@]}"
"$py" -c "
import json, sys
a, b = json.load(open('$work/edited.json')), json.load(open('$work/body'))
a['flame']['xforms'][1]['variations'][1]['params'] = {}  # swirl has none
sys.exit(a['maps'] != b['maps'] or a['flame'] != b['flame'])" &&
  pass "the saved flame reads back as the document saved" || fail "reopened: $(head -c 300 "$work/body")"
if command -v flam3-render >/dev/null; then
  # flam3-render draws the saved file as ifsfx does: as alike as two flam3 seeds are, less 0.05
  for seed in 1 2; do
    env out="$work/flam3-$seed.png" seed=$seed isaac_seed=$seed transparency=0 format=png verbose=0 \
      flam3-render <folder/edited.flame >/dev/null 2>&1 ||
      fail "flam3-render refused edited.flame"
  done
  "$ifsfx" render folder/edited.flame -q -o "$work/ifsfx-edited.png"
  "$py" "$png_tool" similar "$work/flam3-1.png" "$work/flam3-2.png" "$work/ifsfx-edited.png" 0.05 &&
    pass "flam3-render renders the saved flame as ifsfx does ($("$py" "$png_tool" similar "$work/flam3-1.png" "$work/flam3-2.png" "$work/ifsfx-edited.png" 0.05 2>&1))" ||
    fail "flam3-render and ifsfx differ on edited.flame: $("$py" "$png_tool" similar "$work/flam3-1.png" "$work/flam3-2.png" "$work/ifsfx-edited.png" 0.05 2>&1)"
fi
bad_flame() {  # bad_flame WHAT PYTHON_EDIT EXPECTED_MESSAGE_PART [FILE]: a refused flame request
  "$py" -c "
import json
d = json.load(open('$work/spiral.json'))
$2
json.dump(d, open('$work/bad.json', 'w'))"
  expect 400 "$1" POST "/api/${4:-render}" "${auth[@]}" "${jsonh[@]}" --data "@$work/bad.json"
  grep -qF "$3" "$work/body" || fail "$1: the message $(cat "$work/body") lacks '$3'"
}
bad_flame "an unknown variation" "d['flame']['xforms'][0]['variations'][0]['name'] = 'nope'" 'flame.xforms[0].variations[0].name: a variation'
bad_flame "an unknown parameter" "d['flame']['xforms'][0]['variations'][1]['params']['power'] = 2" 'the parameters of julian (got \"power\")'
bad_flame "a weight that is no number" "d['flame']['xforms'][1]['weight'] = 'x'" 'flame.xforms[1].weight: must be a finite number'
bad_flame "a negative weight (the reader's rule)" "d['flame']['xforms'][1]['weight'] = -1" 'xform 1: weight: must be >= 0'
bad_flame "one xform for two maps" "d['flame']['xforms'].pop()" 'one per map'
bad_flame "a palette of 3 colours" "d['flame']['palette']['colours'] = d['flame']['palette']['colours'][:3]" 'must be 256 colours'
bad_flame "a flame's exact descent" "d['mode'] = 'tops'; d['exact'] = True" 'exact'
bad_flame "a colouring of 3 maps for a flame of 2 xforms" "d['mode'] = 'steal'; d['colouring'] = [[0.5, 0, 0, 0.5, 0, 0]] * 3" 'one map per xform of the flame (got 3 for 2)'
bad_flame "a flame saved as .toml" "d['file'] = 'spiral.toml'" 'a flame is saved as NAME.flame' save
bad_flame "a flame saved over its file" "d['file'] = 'pair.flame'" 'pair.flame' save
bad_flame "a flame's filter job with a colouring of 1 map for 2 xforms" "d['movie'] = 'x.mp4'; d['file'] = 'x.mp4'; d['kind'] = 'filter'; d['colouring'] = [[0.5, 0, 0, 0.5, 0, 0]]" 'one map per xform of the flame (got 1 for 2)' jobs
expect 404 "a flame that is not in the file" GET "/api/preset?file=pair.flame&entry=nothing" "${auth[@]}"
expect 400 "the unusable flame" GET "/api/preset?file=pair.flame&entry=2" "${auth[@]}"

# Sources: the folder's images, shown as RGBA at most 1024 pixels a side
expect 200 "sources" GET /api/sources "${auth[@]}"
[[ $(json "d") == "['sample', 'photo.png']" ]] && pass "sources: sample and photo.png" || fail "sources: $(cat "$work/body")"
expect 200 "the sample source" GET "/api/source?name=sample" "${auth[@]}"
[[ $(header X-Ifsfx-Size) == 320x240 && $(stat -c %s "$work/body") == $((320 * 240 * 4)) ]] &&
  pass "source: 320x240 RGBA" || fail "source: $(header X-Ifsfx-Size), $(stat -c %s "$work/body") bytes"
"$py" "$png_tool" write folder/wide.png 3000 20
expect 200 "a wide source" GET "/api/source?name=wide.png" "${auth[@]}"
[[ $(header X-Ifsfx-Size) == 1024x7 && $(header X-Ifsfx-Source-Size) == 3000x20 ]] &&
  pass "a 3000x20 source is shown at 1024x7" || fail "wide source: $(header X-Ifsfx-Size) of $(header X-Ifsfx-Source-Size)"
expect 400 "a source out of the folder" GET "/api/source?name=..%2Fx.png" "${auth[@]}"
expect 404 "a missing source" GET "/api/source?name=missing.png" "${auth[@]}"
expect 400 "a source that is no image" GET "/api/source?name=mixed.ifs" "${auth[@]}"

# Uploads: images only, under a free name, through the output policy
expect 200 "upload an image" POST "/api/upload?name=drop.png" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@folder/photo.png"
[[ $(json "d['saved']") == drop.png ]] && cmp -s folder/drop.png folder/photo.png && pass "upload: drop.png" || fail "upload: $(cat "$work/body")"
expect 200 "upload it again" POST "/api/upload?name=drop.png" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@folder/photo.png"
[[ $(json "d['saved']") == drop-2.png && -f folder/drop-2.png ]] && pass "upload again: drop-2.png, drop.png kept" || fail "upload again: $(cat "$work/body")"
expect 400 "upload bytes that are no image" POST "/api/upload?name=fake.png" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@folder/mixed.ifs"
[[ ! -e folder/fake.png ]] || fail "upload of no image left fake.png"
expect 400 "upload under a name that is no image's" POST "/api/upload?name=notes.txt" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@folder/photo.png"
expect 400 "upload out of the folder" POST "/api/upload?name=..%2Fdrop.png" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@folder/photo.png"
expect 400 "upload under a hidden name" POST "/api/upload?name=.drop.png" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@folder/photo.png"
"$py" "$png_tool" write "$work/huge.png" 8193 1
expect 400 "upload of 8193 pixels a side" POST "/api/upload?name=huge.png" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@$work/huge.png"
head -c $((33 * 1024 * 1024)) /dev/zero >"$work/big.bin"
expect 413 "upload of 33 MiB" POST "/api/upload?name=big.png" "${auth[@]}" -H 'Content-Type: application/octet-stream' --data-binary "@$work/big.bin"
[[ ! -e folder/huge.png && ! -e folder/big.png ]] || fail "refused uploads left files"
[[ -z $(find folder -name '.*') && -z $(ls -A "$work/tmp"/*/ 2>/dev/null | grep -v '^$' | grep -v 'render' ) ]] || fail "uploads left temporary files: $(find folder "$work/tmp" -name '.*' -o -name 'upload-*')"
expect 200 "still answers" GET /api/presets "${auth[@]}"

# A newer render cancels the one in flight: the first answers 409
curl -s -o /dev/null -w '%{http_code}' "${auth[@]}" -X POST "$base/api/render" \
  --data "${preset/#\{/\{\"mode\": \"measure\", \"size\": \"2048x2048\", \"quality\": 4000,}" >"$work/first" &
first=$!
sleep 0.5
c=$(code POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"mode\": \"tops\", \"size\": \"64x64\",}")
wait $first
[[ $(cat "$work/first") == 409 && $c == 200 ]] && pass "a newer render cancels the one in flight (409, then 200)" ||
  fail "cancel: first $(cat "$work/first"), second $c"

# A connection held open (a browser tab keeps some): the stop does not wait for it
exec 3<>"/dev/tcp/127.0.0.1/$port"
printf 'GET /api/presets HTTP/1.1\r\nHost: 127.0.0.1:%s\r\nX-Ifsfx-Token: %s\r\n\r\n' "$port" "$token" >&3
sleep 0.3
stop_check INT 130
exec 3>&-
# Never over an input: the preset the studio was started with
start_studio "$work/folder/fern.toml"
c=$(code POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"fern.toml\",}"); [[ $c == 400 ]] && pass "save over the opened preset: 400 ($(cat "$work/body"))" || fail "save over the opened preset: $c"
# SIGTERM in the middle of a long render
curl -s -o /dev/null "-H" "X-Ifsfx-Token: $token" -X POST "$base/api/render" \
  --data "${preset/#\{/\{\"mode\": \"measure\", \"size\": \"2048x2048\", \"quality\": 4000,}" &
sleep 0.5
stop_check TERM 143
wait

# --listen: other machines may connect (a warning says so); the token and the Host rule still hold
start_studio barnsley-fern --listen 0.0.0.0
grep -q "^ifsfx: warning: studio: listening on 0.0.0.0 port $port: other machines can connect" "$work/stderr" &&
  pass "--listen 0.0.0.0: the warning" || fail "--listen 0.0.0.0: no warning ($(cat "$work/stderr"))"
[[ $url == http://127.0.0.1:$port/* ]] && pass "--listen 0.0.0.0: the URL names 127.0.0.1" || fail "--listen URL $url"
c=$(code GET /api/presets "${auth[@]}" -H "Host: 192.0.2.7:$port"); [[ $c == 200 ]] && pass "--listen 0.0.0.0: an address as Host: 200" || fail "--listen 0.0.0.0: an address as Host: $c"
c=$(code GET /api/presets "${auth[@]}" -H "Host: evil.example:$port"); [[ $c == 403 ]] && pass "--listen 0.0.0.0: another name as Host: 403" || fail "--listen 0.0.0.0: another name: $c"
c=$(code GET /api/presets "${auth[@]}" -H "Origin: http://evil.example:$port"); [[ $c == 403 ]] && pass "--listen 0.0.0.0: bad Origin: 403" || fail "--listen 0.0.0.0: bad Origin: $c"
c=$(code GET /api/presets -H "Host: 192.0.2.7:$port"); [[ $c == 403 ]] && pass "--listen 0.0.0.0: no token: 403" || fail "--listen 0.0.0.0: no token: $c"
kill -INT "$pid"; wait "$pid"
out=$("$ifsfx" studio --listen example.com --folder "$work/folder" 2>&1); rc=$?
[[ $rc == 2 && $out == "ifsfx: --listen: must be an IPv4 or IPv6 address"* ]] && pass "--listen NAME: refused ($out)" ||
  fail "--listen NAME: exit $rc ($out)"

# --source: a relative name not in the current folder is found in --folder, and is the session's
# image (the page selects it); in neither place, the error names both places looked in
start_studio barnsley-fern --source photo.png
c=$(code GET /api/session "${auth[@]}")
[[ $c == 200 && $(json "d['source']['kind'] + ' ' + d['source']['file']") == "image photo.png" ]] &&
  pass "--source photo.png, in --folder: the session's image" || fail "--source in --folder: $c $(cat "$work/body")"
c=$(code GET /api/sources "${auth[@]}"); [[ $(json "d[1]") == @source ]] && pass "--source: @source among the sources" || fail "--source sources: $(cat "$work/body")"
kill -INT "$pid"; wait "$pid"
here=$(pwd -P)
out=$(TMPDIR="$work/tmp" "$ifsfx" studio --source nowhere.png --folder "$work/folder" 2>&1); rc=$?
[[ $rc != 0 && $out == *"--source nowhere.png: no such file (looked for $here/nowhere.png and $here/folder/nowhere.png)"* ]] &&
  pass "--source in neither place: exit $rc ($out)" || fail "--source nowhere: exit $rc ($out)"
[[ -z $(ls -A "$work/tmp") ]] || fail "--source nowhere: left $(ls -A "$work/tmp")"

((failures == 0)) || { echo "$failures failure(s)"; exit 1; }
echo "all passed"
