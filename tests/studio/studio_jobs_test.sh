#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `ifsfx studio`'s render jobs, fit, video, camera and superIFS endpoints on the real binary
# (docs/studio.md), with curl: each endpoint's answer and error paths (token, Host, Origin, plain
# names only, size caps, 4xx with a JSON error, the server still up); the files of the jobs equal
# the command line's (a still byte for byte as `ifsfx render`, a texture sequence as `ifsfx
# texture`, the filtered movie's frames as `ifsfx filter`'s, a fit without time cap as `ifsfx
# fit`'s preset); cancelled jobs leave no file but the movie filter's playable partial; two jobs
# never write the same file; SIGINT with jobs running stops within IFSFX_STOP_BOUND_MS (default
# 500) and leaves no temporary file. Tiny sizes: it runs in the Release and the sanitizer passes.
# Usage: studio_jobs_test.sh IFSFX WORKDIR
set -uo pipefail
# shellcheck source=studio_start.sh
source "$(dirname "$0")/studio_start.sh"
ifsfx=$1
work=$2
bound_ms=${IFSFX_STOP_BOUND_MS:-500}
budget=${IFSFX_JOB_BUDGET_S:-60}  # seconds a small job may take before the test gives up
web=$(cd "$(dirname "$0")/../../studio/web" && pwd)
rm -rf "$work" && mkdir -p "$work/folder" "$work/tmp" "$work/elsewhere"
cd "$work" || exit 1
for tool in curl ffmpeg ffprobe python3; do
  command -v $tool >/dev/null || { echo "SKIP: $tool is missing"; exit 77; }
done
failures=0
fail() { echo "FAIL [${SECONDS}s]: $*"; failures=$((failures + 1)); }
pass() { echo "ok [${SECONDS}s]: $*"; }
check() { # check WHAT CONDITION...
  local what=$1
  shift
  if "$@"; then pass "$what"; else fail "$what"; fi
}

# The inputs: two tiny movies (one outside the folder, for --source), a photo, a shape with alpha.
ffmpeg -v error -y -f lavfi -i "testsrc2=size=96x64:rate=25" -frames:v 12 -c:v mpeg4 -q:v 3 folder/clip.mp4
ffmpeg -v error -y -f lavfi -i "testsrc2=size=96x64:rate=25" -frames:v 6 -c:v mpeg4 -q:v 3 elsewhere/source.mp4
ffmpeg -v error -y -f lavfi -i "testsrc2=size=320x240:rate=25" -frames:v 400 -c:v mpeg4 -q:v 5 folder/long.mp4
cp "$web/sample.png" folder/photo.png
"$ifsfx" render sierpinski-triangle --mode tops --size 48x48 -q -o folder/shape.png
echo '<script>alert(1)</script>' >folder/page.html
ln -s /etc/hostname folder/out.png
ln -s /etc/hostname folder/link.mp4

pid=

# code METHOD PATH [curl args...]: the HTTP status; the body in $work/body
code() {
  local method=$1 path=$2
  shift 2
  curl -s -o "$work/body" -w '%{http_code}' -X "$method" "$@" "$base$path"
}
field() { python3 -c "import json,sys; d=json.load(open('$work/body')); print($1)" 2>/dev/null; }
has_error() { grep -q '"error"' "$work/body"; }
job_id() { sed -n 's/.*"id":\([0-9]*\).*/\1/p' "$work/body"; }

# wait_job ID: until the job ends; its JSON in $work/body, its state printed
wait_job() {
  local state
  for _ in $(seq $((budget * 10))); do
    code GET "/api/jobs/$1" "${auth[@]}" >/dev/null
    state=$(grep -o '"state":"[a-z]*"' "$work/body" | cut -d'"' -f4)
    [[ $state == queued || $state == running ]] || { echo "$state"; return; }
    sleep 0.1
  done
  echo "timeout"
}
hidden_files() { find "$work/folder" -name '.*' | wc -l; }

start_studio barnsley-fern --source "$work/elsewhere/source.mp4"

# ---- the token, Host and Origin on the new endpoints ----
for path in /api/jobs /api/session /api/movies /api/superifs "/api/file?name=clip.mp4"; do
  c=$(code GET "$path"); [[ $c == 403 ]] && has_error || fail "no token on $path: $c"
done
pass "no token: 403 on every new endpoint"
c=$(code POST "/api/fit?maps=2" --data-binary @folder/shape.png); [[ $c == 403 ]] && pass "fit upload without token: 403" || fail "fit upload without token: $c"
c=$(code POST /api/jobs "${auth[@]}" -H "Origin: http://evil.example" --data '{"kind": "still"}'); [[ $c == 403 ]] && pass "job from another origin: 403" || fail "job from another origin: $c"
c=$(code GET /api/jobs "${auth[@]}" -H "Host: evil.example:$port"); [[ $c == 403 ]] && pass "jobs under another Host: 403" || fail "jobs under another Host: $c"
for f in api.js jobs.js fit.js video.js superifs.js extras.css; do
  c=$(code GET "/$f"); [[ $c == 200 ]] || fail "/$f: $c"
done
pass "the panels' files are served"
grep -Eq 'https?://' "$web"/{api,jobs,fit,video,superifs}.js "$web/extras.css" && fail "a panel names an external URL" || pass "the panels name no external URL"

# ---- the session, movies and the video frames ----
c=$(code GET /api/session "${auth[@]}")
[[ $c == 200 && $(field "d['source']['kind'], d['source']['name'], d['camera']") == "movie @source None" ]] &&
  pass "session: the --source movie, no camera" || fail "session: $c $(cat body)"
c=$(code GET /api/movies "${auth[@]}")
[[ $(field "d") == "['@source', 'clip.mp4', 'long.mp4']" ]] && pass "movies: @source and the folder's movies (no link out)" || fail "movies: $(cat body)"
c=$(code GET "/api/video/info?movie=clip.mp4" "${auth[@]}")
[[ $c == 200 && $(field "d['frames'], d['width'], d['height'], d['fps']") == "12 96 64 25.0" ]] && pass "video info: 12 frames 96x64 at 25 fps" || fail "video info: $c $(cat body)"
c=$(code GET "/api/video/info?movie=@source" "${auth[@]}"); [[ $c == 200 && $(field "d['frames']") == 6 ]] && pass "video info of --source (outside the folder)" || fail "video info of @source: $c $(cat body)"
c=$(code GET "/api/video/info?movie=none.mp4" "${auth[@]}"); [[ $c == 404 ]] && has_error && pass "video info of a missing movie: 404" || fail "missing movie: $c"
c=$(code GET "/api/video/info?movie=../elsewhere/source.mp4" "${auth[@]}"); [[ $c == 400 ]] && pass "video info of ../: 400" || fail "video ../: $c"
c=$(code GET "/api/video/info?movie=photo.png" "${auth[@]}"); [[ $c == 400 ]] && pass "video info of an image: 400" || fail "video of an image: $c"
c=$(code GET "/api/video/info?movie=link.mp4" "${auth[@]}"); [[ $c == 400 ]] && pass "video info of a link out of the folder: 400" || fail "video link out: $c"

code GET "/api/preset?name=barnsley-fern" "${auth[@]}" >/dev/null
preset=$(cat body)
with() { printf '%s' "${preset/#\{/\{$1,}"; }  # the preset with more fields
jpeg_size() { ffprobe -v error -show_entries stream=width,height -of csv=p=0 "$1"; }
c=$(code POST /api/video/frame "${auth[@]}" -H "X-Ifsfx-Client: t1" --data "$(with '"movie": "clip.mp4", "frame": 5')")
cp body frame5.jpg
[[ $c == 200 && $(jpeg_size frame5.jpg) == "96,64" ]] && pass "a filtered frame: JPEG 96x64" || fail "video frame: $c $(head -c 200 body)"
c=$(code POST /api/video/frame "${auth[@]}" -H "X-Ifsfx-Client: t1" --data "$(with '"movie": "clip.mp4", "frame": 6, "width": 48')")
[[ $c == 200 && $(jpeg_size body) == "48,32" ]] && pass "a frame at width 48: 48x32" || fail "video frame width: $c $(jpeg_size body)"
c=$(code POST /api/video/frame "${auth[@]}" -H "X-Ifsfx-Client: t2" --data "$(with '"movie": "clip.mp4", "frame": 5')")
cmp -s body frame5.jpg && pass "frame 5 is the same from another tab" || fail "frame 5 differs between tabs"
c=$(code POST /api/video/frame "${auth[@]}" --data "$(with '"movie": "clip.mp4", "frame": 5, "filter": false')")
[[ $c == 200 ]] && ! cmp -s body frame5.jpg && pass "frame 5 unfiltered differs from filtered" || fail "unfiltered frame: $c"
swapped='[[0.5, 0, 0, 0.5, 0.5, 0.5], [0.5, 0, 0, 0.5, 0, 0.5], [0.5, 0, 0, 0.5, 0.5, 0], [0.5, 0, 0, 0.5, 0, 0]]'
c=$(code POST /api/video/frame "${auth[@]}" -H "X-Ifsfx-Client: t1" --data "$(with "\"movie\": \"clip.mp4\", \"frame\": 5, \"colouring\": $swapped")")
[[ $c == 200 ]] && ! cmp -s body frame5.jpg && pass "frame 5 through the editor's colouring IFS differs" || fail "colouring frame: $c"
c=$(code POST /api/video/frame "${auth[@]}" --data "$(with '"movie": "clip.mp4", "frame": 5, "colouring": [[0.5, 0, 0, 0.5, 0, 0]]')"); [[ $c == 400 ]] && pass "a colouring of the wrong count: 400" || fail "colouring count: $c"
c=$(code POST /api/video/frame "${auth[@]}" --data "$(with '"movie": "@source", "frame": 5, "animate": "drift", "drift_amount": 0.2')")
[[ $c == 200 ]] && pass "a drifting frame of --source" || fail "drift frame: $c $(head -c 200 body)"
c=$(code POST /api/video/frame "${auth[@]}" --data "$(with '"movie": "clip.mp4", "frame": 12')"); [[ $c == 400 ]] && has_error && pass "a frame beyond the end: 400 ($(cat body))" || fail "frame beyond: $c"
c=$(code POST /api/video/frame "${auth[@]}" --data "$(with '"movie": "clip.mp4", "frame": 1, "drift_amount": -1')"); [[ $c == 400 ]] && pass "a negative drift: 400" || fail "negative drift: $c"
c=$(code POST /api/video/frame "${auth[@]}" -H "X-Ifsfx-Client: ../x" --data "$(with '"movie": "clip.mp4", "frame": 1')"); [[ $c == 400 ]] && pass "a bad tab id: 400" || fail "bad tab id: $c"
c=$(code POST /api/video/frame "${auth[@]}" --data '{"movie": "clip.mp4", "maps": [[1.5, 0, 0, 1.5, 0, 0]]}'); [[ $c == 400 ]] && pass "an expansive IFS on a frame: 400" || fail "expansive frame: $c"
c=$(code POST /api/camera/frame "${auth[@]}" --data "$preset"); [[ $c == 404 ]] && has_error && pass "camera without --camera: 404 ($(cat body))" || fail "camera without --camera: $c"

# ---- a still job: byte for byte `ifsfx render` of the saved TOML ----
code POST /api/save "${auth[@]}" --data "$(with '"file": "fern.toml"')" >/dev/null
for args in "tops 96x96" "steal 64x48 photo.png"; do
  read -r mode size source <<<"$args"
  extra="\"kind\": \"still\", \"file\": \"still-$mode.png\", \"mode\": \"$mode\", \"size\": \"$size\""
  cli=()
  [[ -n $source ]] && extra+=", \"source\": \"$source\"" && cli=(--source "folder/$source")
  c=$(code POST /api/jobs "${auth[@]}" --data "$(with "$extra")")
  id=$(job_id)
  [[ $c == 202 && $(wait_job "$id") == done && $(field "d['files']") == "['still-$mode.png']" ]] || fail "still $mode: $c $(cat body)"
  "$ifsfx" render folder/fern.toml --mode "$mode" --size "$size" "${cli[@]}" -q -o "cli-$mode.png"
  cmp -s "folder/still-$mode.png" "cli-$mode.png" && pass "still job $mode $size: byte for byte ifsfx render" ||
    fail "still job $mode: differs from ifsfx render"
done
c=$(code GET "/api/file?name=still-tops.png" "${auth[@]}" -D headers)
cmp -s body folder/still-tops.png && grep -qi '^Content-Type: image/png' headers && pass "the still served from the folder" || fail "file: $c"
c=$(code GET "/api/file?name=clip.mp4" "${auth[@]}" -r 0-99); [[ $c == 206 && $(stat -c %s body) == 100 ]] && pass "a movie served by ranges (206)" || fail "range: $c"
c=$(code GET "/api/file?name=page.html" "${auth[@]}" -D headers)
grep -qi '^Content-Disposition: attachment' headers && grep -qi 'sandbox' headers && pass "an HTML file of the folder only as a download, sandboxed" || fail "page.html served inline"
c=$(code GET "/api/file?name=../stdout" "${auth[@]}"); [[ $c == 400 ]] && has_error && pass "file ../: 400" || fail "file ../: $c"
c=$(code GET "/api/file?name=out.png" "${auth[@]}"); [[ $c == 400 ]] && pass "file leading out of the folder: 400" || fail "file link out: $c"
c=$(code GET "/api/file?name=none.png" "${auth[@]}"); [[ $c == 404 ]] && pass "missing file: 404" || fail "missing file: $c"

# The output policy and the names: 4xx before anything is queued
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "still", "file": "photo.png", "mode": "steal", "source": "photo.png", "size": "32x32"')"); [[ $c == 400 ]] && has_error && pass "a still over its source: 400 ($(cat body))" || fail "still over its source: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "still", "file": "../x.png"')"); [[ $c == 400 && ! -e x.png ]] && pass "a still to ../x.png: 400" || fail "still ../: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "still", "file": "x.toml"')"); [[ $c == 400 ]] && pass "a still to .toml: 400" || fail "still .toml: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "still", "file": ".hidden.png"')"); [[ $c == 400 ]] && pass "a still to a hidden name: 400" || fail "still hidden: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "still", "file": "a.png", "size": "5000x5000"')"); [[ $c == 400 ]] && pass "a still above 4096x4096: 400" || fail "still too large: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "nothing"')"); [[ $c == 400 ]] && pass "an unknown kind: 400" || fail "unknown kind: $c"
c=$(code POST /api/jobs "${auth[@]}" --data '{"kind": "still", "file": "a.png", "maps": [[2, 0, 0, 2, 0, 0]]}'); [[ $c == 400 ]] && pass "a still of an expansive IFS: 400" || fail "expansive still: $c"
c=$(code POST /api/jobs "${auth[@]}" --data '{"kind": "still", "file": "a.png"'); [[ $c == 400 ]] && pass "malformed JSON: 400" || fail "malformed job JSON: $c"
head -c 2000000 /dev/zero | tr '\0' ' ' >big.json
c=$(code POST /api/jobs "${auth[@]}" --data-binary @big.json); [[ $c == 413 ]] && has_error && pass "a 2 MB job request: 413" || fail "2 MB job: $c"
for path in /api/jobs/999 /api/jobs/999/preview /api/jobs/99999999999999; do
  c=$(code GET "$path" "${auth[@]}"); [[ $c == 404 ]] || fail "$path: $c"
done
c=$(code POST /api/jobs/999/cancel "${auth[@]}" --data ''); [[ $c == 404 ]] && pass "unknown jobs: 404" || fail "cancel unknown: $c"

# ---- the movie filter: the frames of `ifsfx filter` ----
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "clip.mp4", "file": "filtered.mp4"')")
id=$(job_id)
[[ $c == 202 && $(wait_job "$id") == done && $(field "d['files']") == "['filtered.mp4']" ]] || fail "filter job: $c $(cat body)"
"$ifsfx" filter folder/clip.mp4 --preset folder/fern.toml -q -o cli-filtered.mp4
framemd5() { ffmpeg -v error -i "$1" -map 0:v -f framemd5 - | grep -v '^#'; }
[[ -s folder/filtered.mp4 && $(framemd5 folder/filtered.mp4) == $(framemd5 cli-filtered.mp4) ]] &&
  pass "filter job: the frames of ifsfx filter" || fail "filter job: frames differ from ifsfx filter"
# A flame as the filter (its xforms through the chaos game): the frames of `ifsfx filter --preset
# FILE.flame`.
cat >folder/swirl.flame <<'XML'
<flame name="swirl" size="64 48" center="0 0" scale="18" palette="7">
  <xform weight="0.6" color="0" linear="0.7" swirl="0.3" coefs="0.6 0.2 -0.2 0.6 0.4 0"/>
  <xform weight="0.4" color="1" spherical="0.5" linear="0.5" coefs="0.5 0 0 0.5 -0.4 0.2"/>
</flame>
XML
code GET "/api/preset?file=swirl.flame" "${auth[@]}" >/dev/null
python3 -c "import json; d = json.load(open('body')); d.update(kind='filter', movie='clip.mp4', file='flame-filtered.mp4'); json.dump(d, open('flame-job.json', 'w'))"
c=$(code POST /api/jobs "${auth[@]}" -H 'Content-Type: application/json' --data @flame-job.json)
id=$(job_id)
[[ $c == 202 && $(wait_job "$id") == done ]] || fail "flame filter job: $c $(cat body)"
"$ifsfx" filter folder/clip.mp4 --preset folder/swirl.flame -q -o cli-flame-filtered.mp4
[[ -s folder/flame-filtered.mp4 && $(framemd5 folder/flame-filtered.mp4) == $(framemd5 cli-flame-filtered.mp4) ]] &&
  pass "a flame's filter job: the frames of ifsfx filter --preset FILE.flame" || fail "flame filter job: frames differ from ifsfx filter"
# A named exact descent does nothing for a flame (its steal map comes from the chaos game): the
# job and the preview frame refuse it, as `ifsfx filter --exact` does.
python3 -c "import json; d = json.load(open('flame-job.json')); d.update(exact=True, file='flame-exact.mp4'); json.dump(d, open('flame-exact.json', 'w')); d.pop('kind'); d.pop('file'); d.update(frame=1); json.dump(d, open('flame-exact-frame.json', 'w'))"
c=$(code POST /api/jobs "${auth[@]}" -H 'Content-Type: application/json' --data @flame-exact.json)
[[ $c == 400 ]] && grep -q "exact: the exact descent follows inverse maps" body && [[ ! -e folder/flame-exact.mp4 ]] &&
  pass "a flame filter job with exact: 400 ($(cat body))" || fail "flame job with exact: $c $(cat body)"
c=$(code POST /api/video/frame "${auth[@]}" -H 'Content-Type: application/json' --data @flame-exact-frame.json)
[[ $c == 400 ]] && grep -q "exact: the exact descent" body && pass "a flame's preview frame with exact: 400" || fail "flame frame with exact: $c $(cat body)"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "clip.mp4", "file": "clip.mp4"')"); [[ $c == 400 ]] && pass "a filter over its movie: 400" || fail "filter over input: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "clip.mp4", "file": "x.png"')"); [[ $c == 400 ]] && pass "a filter into .png: 400" || fail "filter to png: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "clip.mp4", "file": "x.mp4", "frames": "9:2"')"); [[ $c == 400 ]] && pass "a bad frame range: 400" || fail "bad range: $c"

# Cancelled: a playable partial movie of the frames done, as `ifsfx filter` keeps; two jobs never
# write one file.
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "long.mp4", "file": "long-out.mp4", "animate": "drift", "size": "960x720"')")
long=$(job_id)
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "clip.mp4", "file": "long-out.mp4"')"); [[ $c == 409 ]] && has_error && pass "a second job writing the same file: 409 ($(cat body))" || fail "same output twice: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "clip.mp4", "file": "long.mp4"')"); [[ $c == 409 ]] && has_error && pass "writing a file a job reads: 409 ($(cat body))" || fail "writing a job's input: $c"
for _ in $(seq $((budget * 10))); do  # until some frames are done
  code GET "/api/jobs/$long" "${auth[@]}" >/dev/null
  grep -q '"phase":"filtering"' body && break
  sleep 0.1
done
c=$(code POST "/api/jobs/$long/cancel" "${auth[@]}" --data '')
state=$(wait_job "$long")
partial=$(field "d['files'][0] if d['files'] else ''")
frames=$([[ -n $partial ]] && ffprobe -v error -count_frames -show_entries stream=nb_read_frames -of csv=p=0 "folder/$partial")
[[ $state == cancelled && $partial == long-out.partial.mp4 && $frames -gt 0 && ! -e folder/long-out.mp4 ]] &&
  pass "a cancelled filter job keeps a playable $partial of $frames frames" || fail "cancelled filter: $state '$partial' $frames $(cat body)"

# A cancelled still leaves no file
c=$(code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "still", "file": "big.png", "mode": "measure", "size": "2048x2048", "quality": 4000')")
id=$(job_id)
sleep 0.3
code POST "/api/jobs/$id/cancel" "${auth[@]}" --data '' >/dev/null
[[ $(wait_job "$id") == cancelled && ! -e folder/big.png && $(hidden_files) == 0 ]] && pass "a cancelled still leaves no file" || fail "cancelled still: $(cat body)"
# At most 16 pending jobs
for i in $(seq 17); do
  c=$(code POST /api/jobs "${auth[@]}" --data "$(with "\"kind\": \"still\", \"file\": \"q$i.png\", \"mode\": \"measure\", \"size\": \"2048x2048\", \"quality\": 4000")")
  [[ $c == 202 ]] || break
done
[[ $c == 429 ]] && has_error && pass "the 17th pending job: 429" || fail "job limit: $c after $i"
code GET /api/jobs "${auth[@]}" >/dev/null
for id in $(field "' '.join(str(j['id']) for j in d['jobs'] if j['state'] in ('queued', 'running'))"); do
  code POST "/api/jobs/$id/cancel" "${auth[@]}" --data '' >/dev/null
done
for _ in $(seq $((budget * 10))); do
  code GET /api/jobs "${auth[@]}" >/dev/null
  grep -Eq '"state":"(queued|running)"' body || break
  sleep 0.1
done
ls folder/q*.png >/dev/null 2>&1 && fail "cancelled jobs left files" || pass "16 jobs cancelled, no file left"

# ---- superIFS: open, save, textures, a texture-sequence job as `ifsfx texture` ----
c=$(code GET /api/superifs "${auth[@]}"); [[ $c == 200 && $(field "'paper-fig4' in [s['name'] for s in d['shipped']]") == True ]] && pass "superIFS list" || fail "superifs list: $c"
c=$(code GET "/api/superifs/preset?name=paper-fig4" "${auth[@]}")
super=$(cat body)
[[ $c == 200 && $(field "len(d['ifs']), len(d['ifs'][0]['maps'])") == "2 3" ]] && pass "paper-fig4: 2 IFSs of 3 maps" || fail "superifs preset: $c"
c=$(code GET "/api/superifs/preset?name=/etc/passwd" "${auth[@]}"); [[ $c == 404 ]] && pass "superIFS by path: 404" || fail "superifs by path: $c"
c=$(code GET "/api/superifs/preset?file=../x.super.toml" "${auth[@]}"); [[ $c == 400 ]] && pass "superIFS file ../: 400" || fail "superifs file ../: $c"
edited=$(printf '%s' "$super" | python3 -c "import json,sys; d=json.load(sys.stdin); d['ifs'][1]['maps'][0][4]=0.05; d['name']='edited'; print(json.dumps(d))")
c=$(code POST /api/superifs/save "${auth[@]}" --data "{\"superifs\": $edited, \"file\": \"edited.super.toml\"}")
[[ $c == 200 && -f folder/edited.super.toml ]] && pass "superIFS saved" || fail "superifs save: $c $(cat body)"
c=$(code GET "/api/superifs/preset?file=edited.super.toml" "${auth[@]}"); [[ $c == 200 && $(field "d['ifs'][1]['maps'][0][4]") == 0.05 ]] && pass "the saved superIFS opens with the edit" || fail "saved superifs: $c"
c=$(code POST /api/superifs/save "${auth[@]}" --data "{\"superifs\": $edited, \"file\": \"edited.toml\"}"); [[ $c == 400 ]] && pass "superIFS saved as .toml: 400" || fail "superifs .toml: $c"
bad=$(printf '%s' "$super" | python3 -c "import json,sys; d=json.load(sys.stdin); d['ifs'][0]['maps'][0][0]=1.5; print(json.dumps(d))")
c=$(code POST /api/texture/frame "${auth[@]}" --data "{\"superifs\": $bad}"); [[ $c == 400 ]] && has_error && pass "an expansive superIFS: 400 ($(cat body))" || fail "expansive superifs: $c"
bad=$(printf '%s' "$super" | python3 -c "import json,sys; d=json.load(sys.stdin); d['ifs'][0]['maps'].pop(); print(json.dumps(d))")
c=$(code POST /api/texture/frame "${auth[@]}" --data "{\"superifs\": $bad}"); [[ $c == 400 ]] && pass "IFSs of different map counts: 400" || fail "map counts: $c"
for k in 0 1; do
  c=$(code POST /api/texture/frame "${auth[@]}" --data "{\"superifs\": $super, \"size\": \"64x64\", \"step\": $k, \"V\": 2}" -H "X-Ifsfx-Client: t1")
  cp body "texture$k.png"
  [[ $c == 200 && $(jpeg_size "texture$k.png") == "64,64" ]] || fail "texture $k: $c"
done
! cmp -s texture0.png texture1.png && pass "textures 0 and 1: two members of the family" || fail "textures 0 and 1 are equal"
c=$(code POST /api/texture/frame "${auth[@]}" --data "{\"superifs\": $super, \"size\": \"64x64\", \"step\": 0, \"V\": 2}" -H "X-Ifsfx-Client: t2")
cmp -s body texture0.png && pass "texture 0 again (another tab, from the burn-in): the same" || fail "texture 0 differs"
c=$(code POST /api/texture/frame "${auth[@]}" --data "{\"superifs\": $super, \"size\": \"64x64\", \"mode\": \"steal\", \"source\": \"photo.png\"}"); [[ $c == 200 ]] && pass "a steal texture of a folder image" || fail "steal texture: $c"
c=$(code POST /api/texture/frame "${auth[@]}" --data "{\"superifs\": $super, \"V\": 0}"); [[ $c == 400 ]] && pass "V = 0: 400" || fail "V 0: $c"
c=$(code POST /api/texture/frame "${auth[@]}" --data "{\"superifs\": $super, \"size\": \"4096x4096\"}"); [[ $c == 400 ]] && pass "a preview above 1024: 400" || fail "big texture: $c"
c=$(code POST /api/jobs "${auth[@]}" --data "{\"kind\": \"texture\", \"superifs\": $edited, \"file\": \"tex.png\", \"frames\": 3, \"crossfade\": 2, \"size\": \"48x48\", \"V\": 2, \"mode\": \"tops\"}")
id=$(job_id)
[[ $c == 202 && $(wait_job "$id") == done && $(field "d['files']") == "['tex_0001.png', 'tex_0002.png', 'tex_0003.png']" ]] || fail "texture job: $c $(cat body)"
"$ifsfx" texture folder/edited.super.toml --frames 3 --crossfade 2 --size 48x48 -V 2 --mode tops -q -o "cli_%04d.png"
same=1
for i in 1 2 3; do cmp -s "folder/tex_000$i.png" "cli_000$i.png" || same=0; done
((same)) && pass "texture job: 3 frames byte for byte ifsfx texture" || fail "texture job differs from ifsfx texture"
c=$(code POST /api/jobs "${auth[@]}" --data "{\"kind\": \"texture\", \"superifs\": $super, \"file\": \"t.png\", \"frames\": 0}"); [[ $c == 400 ]] && pass "a texture job of 0 frames: 400" || fail "0 frames: $c"

# ---- fit: an uploaded shape, as `ifsfx fit` fits it ----
fit_query="maps=3&seconds=0&evaluations=1500&size=32&name=shape.png"
c=$(code POST "/api/fit?$fit_query" "${auth[@]}" -H "Content-Type: image/png" --data-binary @folder/shape.png)
id=$(job_id)
[[ $c == 202 && $(wait_job "$id") == done ]] || fail "fit: $c $(cat body)"
[[ $(field "len(d['result']['preset']['maps'])") == 3 && $(field "d['result']['iou'] > 0.2") == True ]] &&
  pass "fit of an upload: 3 maps, IoU $(field "round(d['result']['iou'], 3)")" || fail "fit result: $(cat body)"
field "d['result']['toml']" >studio-fit.toml
(cd folder && "$ifsfx" fit shape.png -n 3 --max-seconds 0 --max-evaluations 1500 --size 32 -o ../cli-fit.toml >/dev/null)
# The CLI's file ends with a newline that print() adds once more here.
diff -q <(cat cli-fit.toml) <(head -c -1 studio-fit.toml) >/dev/null && pass "fit without a time cap: the preset of ifsfx fit" || fail "fit differs from ifsfx fit: $(diff cli-fit.toml studio-fit.toml | head -5)"
c=$(code GET "/api/jobs/$id/preview" "${auth[@]}"); [[ $c == 200 ]] && file body | grep -q PNG && pass "fit preview: a PNG" || fail "fit preview: $c"
c=$(code POST /api/fit "${auth[@]}" -H "Content-Type: application/json" --data '{"file": "shape.png", "maps": 2, "seconds": 1, "size": 32}')
id=$(job_id); [[ $c == 202 && $(wait_job "$id") == done ]] && pass "fit of a folder image" || fail "folder fit: $c $(cat body)"
c=$(code POST /api/fit "${auth[@]}" -H "Content-Type: application/json" --data '{"file": "../shape.png"}'); [[ $c == 400 ]] && pass "fit of ../: 400" || fail "fit ../: $c"
c=$(code POST "/api/fit?maps=3" "${auth[@]}" -H "Content-Type: image/png" --data-binary "not an image"); [[ $c == 415 ]] && has_error && pass "fit of something else: 415" || fail "fit garbage: $c"
c=$(code POST "/api/fit?maps=0" "${auth[@]}" -H "Content-Type: image/png" --data-binary @folder/shape.png); [[ $c == 400 ]] && pass "fit of 0 maps: 400" || fail "fit 0 maps: $c"
c=$(code POST "/api/fit?seconds=abc" "${auth[@]}" -H "Content-Type: image/png" --data-binary @folder/shape.png); [[ $c == 400 ]] && pass "fit of seconds=abc: 400" || fail "fit seconds abc: $c"
head -c 34000000 /dev/zero >huge.png
c=$(code POST "/api/fit" "${auth[@]}" -H "Content-Type: image/png" --data-binary @huge.png); [[ $c == 413 ]] && has_error && pass "a 34 MB upload: 413" || fail "34 MB upload: $c"
rm huge.png
c=$(code POST "/api/fit?maps=3&seconds=60&size=64" "${auth[@]}" -H "Content-Type: image/png" --data-binary @folder/shape.png)
id=$(job_id); sleep 0.5
code POST "/api/jobs/$id/cancel" "${auth[@]}" --data '' >/dev/null
[[ $(wait_job "$id") == cancelled ]] && pass "a fit cancelled" || fail "fit cancel: $(cat body)"
[[ -z $(ls -A tmp | grep -v '^ifsfx-studio-') && -z $(ls -A tmp/ifsfx-studio-* 2>/dev/null) ]] && pass "uploads removed from the scratch folder" || fail "scratch holds $(ls -A tmp/*)"

c=$(code GET /api/presets "${auth[@]}"); [[ $c == 200 ]] && pass "the server still answers" || fail "server gone: $c"

# ---- SIGINT with jobs running ----
code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "filter", "movie": "long.mp4", "file": "stopped.mp4"')" >/dev/null
code POST /api/jobs "${auth[@]}" --data "$(with '"kind": "still", "file": "stopped.png", "mode": "measure", "size": "2048x2048", "quality": 4000')" >/dev/null
sleep 0.5
t0=$(date +%s%N)
kill -INT "$pid"
wait "$pid"
rc=$?
ms=$((($(date +%s%N) - t0) / 1000000))
[[ $rc == 130 ]] && pass "SIGINT with jobs running: exit 130" || fail "SIGINT: exit $rc"
((ms <= bound_ms)) && pass "SIGINT with jobs running: stopped in $ms ms" || fail "SIGINT with jobs: $ms ms (> $bound_ms)"
[[ -z $(ls -A tmp) && $(hidden_files) == 0 && ! -e folder/stopped.png && ! -e folder/stopped.mp4 ]] && pass "no temporary file left" || fail "left: $(ls -A tmp) $(find folder -name '.*')"

# ---- the camera: no such device, and a device that fails ----
TMPDIR="$work/tmp" "$ifsfx" studio --folder "$work/folder" --camera /dev/video99 >stdout 2>stderr
rc=$?
[[ $rc != 0 ]] && grep -q '/dev/video99' stderr && pass "--camera /dev/video99: exit $rc, $(cat stderr)" || fail "missing camera: exit $rc $(cat stderr)"
[[ -z $(ls -A tmp) ]] && pass "--camera /dev/video99: no scratch folder left" || fail "missing camera left $(ls -A tmp)"
start_studio barnsley-fern --camera /dev/null
c=$(code GET /api/session "${auth[@]}"); [[ $(field "d['camera']") == /dev/null ]] || fail "session camera: $(cat body)"
c=$(code POST /api/camera/frame "${auth[@]}" --data "$preset")
[[ $c == 503 ]] && grep -q '/dev/null' body && pass "a camera that fails: 503 naming it ($(cat body))" || fail "failing camera: $c $(cat body)"
c=$(code POST /api/camera/frame "${auth[@]}" --data "$preset"); [[ $c == 503 ]] && pass "tried again: 503 again" || fail "camera again: $c"
c=$(code POST /api/camera/stop "${auth[@]}" --data ''); [[ $c == 200 ]] || fail "camera stop: $c"
c=$(code GET /api/presets "${auth[@]}"); [[ $c == 200 ]] && pass "the server keeps running after the camera failed" || fail "server gone after camera: $c"
kill -TERM "$pid"
wait "$pid"
[[ $? == 143 ]] || fail "SIGTERM: not 143"

((failures == 0)) || { echo "$failures failure(s)"; exit 1; }
echo "all passed"
