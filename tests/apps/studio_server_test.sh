#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `ifsfx studio`'s server on the real binary (docs/studio.md): the token, Host and Origin checks,
# bad requests answered with a 4xx and the server still up, a render's PNG equal to `ifsfx render`
# of the same preset and options byte for byte, the output policy of save, a newer render
# cancelling the one in flight, and SIGINT/SIGTERM stopping it within IFSFX_STOP_BOUND_MS
# (default 500) with exit 130/143 and no temporary file left.
# Usage: studio_server_test.sh IFSFX WORKDIR
set -uo pipefail
ifsfx=$1
work=$2
bound_ms=${IFSFX_STOP_BOUND_MS:-500}
web=$(cd "$(dirname "$0")/../../apps/studio/web" && pwd)
rm -rf "$work" && mkdir -p "$work/folder" "$work/tmp"
cd "$work" || exit 1
command -v curl >/dev/null || { echo "SKIP: curl is missing"; exit 77; }
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok: $*"; }

pid=
start_studio() {  # start_studio [PRESET]
  TMPDIR="$work/tmp" "$ifsfx" studio "${1:-barnsley-fern}" --folder "$work/folder" >"$work/stdout" 2>"$work/stderr" &
  pid=$!
  url=
  for _ in $(seq 100); do
    url=$(sed -n 's/^ifsfx studio: //p' "$work/stdout")
    [[ -n $url ]] && break
    sleep 0.1
  done
  [[ -n $url ]] || { cat "$work/stderr"; echo "FAIL: no URL printed"; exit 1; }
  base=${url%%/\?token=*}
  token=${url##*token=}
  port=${base##*:}
  auth=(-H "X-Ifsfx-Token: $token")
}

# code METHOD PATH [curl args...]: the HTTP status
code() {
  local method=$1 path=$2
  shift 2
  curl -s -o "$work/body" -w '%{http_code}' -X "$method" "$@" "$base$path"
}

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

start_studio
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
c=$(code POST /api/render "${auth[@]}" --data-binary "@$work/big.json"); [[ $c == 413 ]] && pass "2 MB body: 413" || fail "2 MB body: $c"
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

# A newer render cancels the one in flight: the first answers 409
curl -s -o /dev/null -w '%{http_code}' "${auth[@]}" -X POST "$base/api/render" \
  --data "${preset/#\{/\{\"mode\": \"measure\", \"size\": \"2048x2048\", \"quality\": 4000,}" >"$work/first" &
first=$!
sleep 0.5
c=$(code POST /api/render "${auth[@]}" --data "${preset/#\{/\{\"mode\": \"tops\", \"size\": \"64x64\",}")
wait $first
[[ $(cat "$work/first") == 409 && $c == 200 ]] && pass "a newer render cancels the one in flight (409, then 200)" ||
  fail "cancel: first $(cat "$work/first"), second $c"

stop_check INT 130
# Never over an input: the preset the studio was started with
start_studio "$work/folder/fern.toml"
c=$(code POST /api/save "${auth[@]}" --data "${preset/#\{/\{\"file\": \"fern.toml\",}"); [[ $c == 400 ]] && pass "save over the opened preset: 400 ($(cat "$work/body"))" || fail "save over the opened preset: $c"
# SIGTERM in the middle of a long render
curl -s -o /dev/null "-H" "X-Ifsfx-Token: $token" -X POST "$base/api/render" \
  --data "${preset/#\{/\{\"mode\": \"measure\", \"size\": \"2048x2048\", \"quality\": 4000,}" &
sleep 0.5
stop_check TERM 143
wait

((failures == 0)) || { echo "$failures failure(s)"; exit 1; }
echo "all passed"
