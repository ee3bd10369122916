# SPDX-License-Identifier: Apache-2.0
# Sourced by the studio's curl tests (studio_server_test.sh, studio_jobs_test.sh), which set
# $ifsfx and $work. start_studio PRESET [OPTION...] starts `ifsfx studio` on $work/folder in the
# background (temporary files in $work/tmp, output in $work/stdout and $work/stderr), waits for
# the URL it prints and sets pid, url, base, token, port and auth (the token header for curl).
start_studio() {
  TMPDIR="$work/tmp" "$ifsfx" studio "$1" "${@:2}" --folder "$work/folder" >"$work/stdout" 2>"$work/stderr" &
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
