#!/usr/bin/env bash
# Checks of `adaptivert` on files a test must make at run time (a FIFO, a file only another user
# may read, a full disk, a write-protected output, raw voxels), one mode per ctest test:
#   files_check.sh ART MODE WORK [SOURCE_DIR]
# Every refusal must be one line naming the file and the cause, exit 1, within a few seconds.
set -uo pipefail
art=$1 mode=$2 work=$3 src=${4:-}
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
# expect EXIT REGEX CMD...: runs CMD (5 s at most), checks its exit code and one-line stderr.
expect() {
  local want=$1 regex=$2
  shift 2
  local err rc
  err=$(timeout 5 "$@" 2>&1 >/dev/null)
  rc=$?
  [ "$rc" = "$want" ] || fail "exit $rc (want $want) from $*: $err"
  [ "$(printf '%s\n' "$err" | wc -l)" = 1 ] || fail "more than one line from $*: $err"
  [[ "$err" =~ $regex ]] || fail "'$err' does not match '$regex'"
}
case $mode in
  fifo)
    mkfifo "$work/scan.mha"
    for cmd in info render reduce; do
      args=("$work/scan.mha")
      [ $cmd = render ] && args+=(-o "$work/out.png")
      [ $cmd = reduce ] && args+=("$work/out.vtu" --tets 100)
      expect 1 "scan.mha: is a FIFO \(named pipe\), not a regular file" "$art" $cmd "${args[@]}"
    done
    ln -s /dev/zero "$work/zero.mha"
    expect 1 "zero.mha: is a character device, not a regular file" "$art" info "$work/zero.mha"
    expect 1 "/dev/zero: is a character device, not a regular file" \
      "$art" render "$src/data/ct-head-128.mha" -o "$work/out.png" --size 20x20 --tf /dev/zero
    ;;
  permission)
    # Root reads anything: the refusal is checked as the user nobody.
    command -v setpriv > /dev/null || { echo "no setpriv: skipped"; exit 77; }
    cp "$src/data/ct-head-128.mha" "$work/private.mha" && chmod 600 "$work/private.mha"
    mkdir -p "$work/closed" && cp "$src/data/ct-head-128.mha" "$work/closed/scan.mha" && chmod 700 "$work/closed"
    chmod 755 "$work"
    as_nobody=(setpriv --reuid=65534 --regid=65534 --clear-groups)
    "${as_nobody[@]}" true 2> /dev/null || { echo "cannot run as nobody: skipped"; exit 77; }
    "${as_nobody[@]}" test -x "$art" || { echo "nobody cannot run $art: skipped"; exit 77; }
    expect 1 "private.mha: permission denied$" "${as_nobody[@]}" "$art" info "$work/private.mha"
    expect 1 "scan.mha: permission denied \(a folder on its path cannot be searched\)" \
      "${as_nobody[@]}" "$art" info "$work/closed/scan.mha"
    ;;
  diskfull)
    # An 8 KB file system in a mount namespace of our own.
    unshare -m true 2> /dev/null || { echo "no mount namespace: skipped"; exit 77; }
    mkdir -p "$work/full"
    unshare -m bash -c "mount -t tmpfs -o size=8k tmpfs '$work/full' || exit 77
      '$art' reduce '$src/data/ct-head-128.mha' '$work/full/mesh.vtu' --tets 2000 --quiet > /dev/null 2> '$work/err.txt'
      echo \$? > '$work/rc.txt'
      '$art' render '$src/data/ct-head-128.mha' -o '$work/full/big.png' --size 800x800 --no-error --quiet \
        > /dev/null 2> '$work/err2.txt'
      echo \$? > '$work/rc2.txt'
      ls -A '$work/full' > '$work/left.txt'"
    [ $? = 77 ] && { echo "cannot mount tmpfs: skipped"; exit 77; }
    [ "$(cat "$work/rc.txt")" = 1 ] || fail "reduce on a full disk: exit $(cat "$work/rc.txt"): $(cat "$work/err.txt")"
    grep -q "mesh.vtu: cannot write mesh: no space left on device" "$work/err.txt" || fail "reduce said: $(cat "$work/err.txt")"
    [ "$(wc -l < "$work/err.txt")" = 1 ] || fail "reduce said more than one line: $(cat "$work/err.txt")"
    [ "$(cat "$work/rc2.txt")" = 1 ] || fail "render on a full disk: exit $(cat "$work/rc2.txt")"
    grep -q "big.png: cannot write image: no space left on device" "$work/err2.txt" || fail "render said: $(cat "$work/err2.txt")"
    [ -s "$work/left.txt" ] && fail "files left on the full disk: $(cat "$work/left.txt")"
    ;;
  protected)
    printf 'precious' > "$work/mesh.vtu" && chmod 444 "$work/mesh.vtu"
    printf 'precious' > "$work/image.png" && chmod 444 "$work/image.png"
    expect 1 "mesh.vtu: exists and is write-protected: not replaced" \
      "$art" reduce "$src/data/ct-head-128.mha" "$work/mesh.vtu" --tets 100 --quiet
    expect 1 "image.png: exists and is write-protected: not replaced" \
      "$art" render "$src/data/am_underworks.ply" -o "$work/image.png" --size 20x20
    [ "$(cat "$work/mesh.vtu")$(cat "$work/image.png")" = preciousprecious ] || fail "a protected file changed"
    ;;
  raw)
    # 2 x 2 x 3 uint16 voxels 0..11 (big-endian) after a 6-byte header.
    { printf 'HEADER'; for v in $(seq 0 11); do printf "\\x00\\x$(printf %02x "$v")"; done; } > "$work/v.raw"
    out=$("$art" info "$work/v.raw" --raw-dims 2,2,3 --raw-type uint16 --raw-endian big --raw-spacing 0.5,1,2 \
      --raw-header 6) || fail "info on raw voxels failed"
    [[ $out =~ dimensions\ +2\ x\ 2\ x\ 3 ]] || fail "dimensions: $out"
    [[ $out =~ spacing\ +0.5\ x\ 1\ x\ 2 ]] || fail "spacing: $out"
    [[ $out =~ range\ 0\ \.\.\ 11 ]] || fail "range: $out"
    expect 1 "v.raw: holds 2 bytes more than its header and 24 data bytes" \
      "$art" info "$work/v.raw" --raw-dims 2,2,3 --raw-type uint16 --raw-header 4
    expect 1 "v.raw: holds 30 data bytes; 2 x 2 x 4 uint16 voxels need 32" \
      "$art" info "$work/v.raw" --raw-dims 2,2,4 --raw-type uint16
    expect 1 "v.raw: a raw volume needs its layout: --raw-dims" "$art" info "$work/v.raw"
    expect 2 "--raw-dims expects X,Y,Z" "$art" info "$work/v.raw" --raw-dims 2,2 --raw-type uint16
    expect 2 "needs both --raw-dims X,Y,Z and --raw-type" "$art" info "$work/v.raw" --raw-dims 2,2,3
    ;;
  frame)
    # A radiological NIfTI (sform x flipped): reduced in the vtk frame it covers the box VTK's
    # reader (and ParaView) give, origin 0 and spacing 2 x 3 x 4; in the patient frame it is turned.
    nii=$src/tests/data/nifti-radiological.nii
    "$art" reduce "$nii" "$work/vtk.vtu" --tets 6 --frame vtk --quiet > /dev/null || fail "reduce --frame vtk"
    "$art" reduce "$nii" "$work/patient.vtu" --tets 6 --quiet > /dev/null || fail "reduce"
    v=$("$art" info "$work/vtk.vtu") p=$("$art" info "$work/patient.vtu")
    [[ $v =~ bounds\ +x\ \[0,\ 6\]\ \ y\ \[0,\ 6\]\ \ z\ \[0,\ 4\] ]] || fail "vtk frame: $v"
    [[ $v =~ field\ data.*Frame ]] || fail "no Frame in the mesh's field data: $v"
    [[ $p =~ bounds\ +x\ \[-10,\ -4\]\ \ y\ \[-26,\ -20\]\ \ z\ \[30,\ 34\] ]] || fail "patient frame: $p"
    i=$("$art" info --json --frame vtk "$nii")
    [[ $i =~ \"frame\":\"VTK\ reader\" ]] || fail "info --json --frame vtk: $i"
    [[ $i =~ \"index_to_world\":\[2,0,0,0,0,3,0,0,0,0,4,0 ]] || fail "index_to_world: $i"
    expect 2 "--frame is patient or vtk, got 'ras'" "$art" info --frame ras "$nii"
    ;;
  batchkill)
    # A SIGKILL of `adaptivert batch` takes the render it runs with it (it kept running).
    cat > "$work/job.json" <<JOB
{ "output": "frames", "datasets": ["$src/data/ct-head-128.mha"], "size": "1000x1000",
  "cameras": [{"azimuth": 0}], "settings": [{"reference": true}] }
JOB
    "$art" batch --quiet "$work/job.json" > /dev/null 2>&1 &
    pid=$!
    for _ in $(seq 100); do
      pgrep -f -- "render .* -o $work/frames/" > /dev/null && break
      sleep 0.1
    done
    pgrep -f -- "render .* -o $work/frames/" > /dev/null || fail "the batch started no render"
    kill -9 "$pid"
    wait "$pid" 2> /dev/null
    sleep 0.5
    if pgrep -f -- "render .* -o $work/frames/" > /dev/null; then
      fail "the render of the killed batch is still running"
    fi
    ;;
  *)
    fail "unknown mode $mode"
    ;;
esac
echo "ok: $mode"
