#!/bin/sh
# Issue 20's hostile command lines, one case per ctest test (tests/shell/CMakeLists.txt):
#   hostile_cli.sh BIN_DIR WORK_DIR CASE
# Each case runs the programs as a careless or hostile user would and checks the exit
# code and the message; a hang is caught by `timeout` (exit 124 fails the case). Run it
# with BIN_DIR = an older build to see the cases fail there.
set -u
bin=$1
work=$2/hostile-$3
case_=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1

fail() {
    echo "FAIL ($case_): $*"
    exit 1
}
# expect CODE REGEX CMD...: runs CMD (20 s at most), its output must match REGEX (grep -E)
# and its exit code be CODE ("nz" = any non-zero but 124, the timeout).
expect() {
    code=$1
    regex=$2
    shift 2
    timeout 20 "$@" >out.txt 2>&1
    rc=$?
    cat out.txt
    echo "exit code $rc"
    [ $rc -eq 124 ] && fail "timed out (hung): $*"
    if [ "$code" = nz ]; then
        [ $rc -ne 0 ] || fail "exit 0, expected non-zero: $*"
    else
        [ $rc -eq "$code" ] || fail "exit $rc, expected $code: $*"
    fi
    # Lines joined, so a regex may span them with .*
    tr '\n' ' ' <out.txt | grep -Eq -- "$regex" || fail "output does not match '$regex': $*"
}

cat >s.nff <<'EOF'
v
from 0 0 5
at 0 0 0
up 0 1 0
angle 45
hither 0.01
resolution 16 16
l 0 5 5
f 1 0 0 1 0 0 0 1
s 0 0 0 1
EOF

case $case_ in
fifo-rt)
    mkfifo fifo.png
    expect nz "fifo.png: is a FIFO" "$bin/rt_render" s.nff --out fifo.png --size 8x8
    ;;
fifo-lab)
    mkfifo fifo.png
    expect nz "fifo.png: is a FIFO" "$bin/lab01-affine" --headless --out fifo.png --size 8x8
    ;;
fifo-spd)
    mkfifo fifo.nff
    expect nz "fifo.nff: is a FIFO" "$bin/spd_generate" balls 1 fifo.nff
    ;;
device-out)
    expect nz "/dev/full: is a device" "$bin/spd_generate" balls 1 /dev/full
    expect nz "/dev/full: is a device" "$bin/rt_render" s.nff --out /dev/full --size 8x8
    ;;
stdout-full)
    timeout 20 "$bin/spd_generate" balls 1 >/dev/full 2>err.txt
    rc=$?
    cat err.txt
    [ $rc -ne 0 ] && [ $rc -ne 124 ] || fail "spd_generate > /dev/full exited $rc"
    grep -q "No space left" err.txt || fail "no errno reason"
    ;;
errno-reason)
    expect nz "/proc/wb-x.nff: cannot open for writing \(" "$bin/spd_generate" balls 1 /proc/wb-x.nff
    ;;
symlink-dangling)
    ln -s "$work/missing.png" dang.png
    expect nz "dang.png: is a symbolic link to a file that does not exist" \
        "$bin/rt_render" s.nff --out dang.png --size 8x8
    [ -L dang.png ] || fail "the link was replaced"
    expect nz "dang.png: is a symbolic link to a file that does not exist" \
        "$bin/lab01-affine" --headless --out dang.png --size 8x8
    [ -L dang.png ] || fail "the link was replaced"
    [ -e missing.png ] && fail "the link's target was created"
    ;;
symlink-loop)
    ln -s loop.png loop.png
    expect nz "loop.png: is a symbolic link that loops" "$bin/rt_render" s.nff --out loop.png --size 8x8
    [ -L loop.png ] || fail "the link was replaced"
    i=0
    ln -s target.png l0.png
    : >target.png
    while [ $i -lt 45 ]; do
        ln -s l$i.png l$((i + 1)).png
        i=$((i + 1))
    done
    expect nz "l45.png: is a symbolic link that loops or passes through more than 40" \
        "$bin/rt_render" s.nff --out l45.png --size 8x8
    [ -L l45.png ] || fail "the chain's link was replaced"
    ;;
symlink-follow)
    : >target.png
    ln -s target.png link.png
    expect 0 "" "$bin/rt_render" s.nff --out link.png --size 8x8
    [ -L link.png ] || fail "the link was replaced"
    [ -s target.png ] || fail "the target was not written"
    ;;
empty-value)
    expect 2 "--out: the value is empty" "$bin/rt_render" s.nff --out "" --size 16x16
    [ -e ./--size=16x16 ] && fail "wrote ./--size=16x16"
    expect 2 "--threads: the value is empty" "$bin/rt_render" s.nff --threads "" --out x.png
    expect nz "--keys: the value is empty" "$bin/lab01-affine" --headless --keys "" --out k.png
    [ -e k.png ] && fail "wrote k.png"
    expect nz "--out: the value is empty" "$bin/lab01-affine" --headless --out= --size 8x8
    ;;
rt-messages)
    for d in 65 -5 1e3 abc; do
        expect 2 "--depth '$d': expected an integer from 0 to 64" "$bin/rt_render" s.nff --depth "$d"
    done
    expect 2 "unknown option '--bogus'" "$bin/rt_render" s.nff --bogus
    expect 2 "one scene file only: 's2.nff' after 's.nff'" "$bin/rt_render" s.nff s2.nff
    expect 2 "'--' is not an option here" "$bin/rt_render" s.nff -- --out x.png
    ;;
workbench-messages)
    expect 2 "unknown option '--bogus'" "$bin/workbench" --headless --bogus
    expect 2 "--ui-scale '9': expected a number from 0.5 to 4" "$bin/workbench" --headless --ui-scale 9
    ;;
render-memory)
    expect nz "a 16384x16384 render with --spd needs about 8.9 GB" \
        "$bin/rt_render" s.nff --size 16384x16384 --spd --out big.png
    [ -e big.png ] && fail "wrote big.png"
    ;;
nff-up-denormal)
    sed 's/^up 0 1 0$/up 0 1e-320 0/' s.nff >d.nff
    expect nz "d.nff:1: bad view: up \(0, 1e-320, 0\) is too small" "$bin/rt_render" d.nff --out x.png
    ;;
nff-nul)
    printf 'v\nfrom 0 0 5\nat 0 0 0\0\n' >nul.nff
    expect nz "nul.nff:3: NUL byte in the line \(a binary file\?\)" "$bin/rt_render" nul.nff --out x.png
    # 64 MB of NUL bytes: refused at once, without the whole file as one token (it took
    # 3x the file in memory before; /usr/bin/time is not needed for the message check).
    head -c 67108864 /dev/zero >zero.nff
    expect nz "zero.nff:1: NUL byte" "$bin/rt_render" zero.nff --out x.png
    ;;
escaped-path)
    esc=$(printf 'a\033[31mb\nc.nff')
    expect nz 'a\\x1b\[31mb\\x0ac.nff:0: cannot open the file' "$bin/rt_render" "$esc" --out x.png
    grep -q "$(printf '\033')" out.txt && fail "a raw escape byte reached the terminal"
    ;;
nff-ior)
    sed 's/^f 1 0 0 1 0 0 0 1$/f 1 0 0 1 0 0 0.5 0/' s.nff >ior.nff
    expect nz "ior.nff:9: index of refraction 0 with T = 0.5" "$bin/rt_render" ior.nff --out x.png
    sed 's/^f 1 0 0 1 0 0 0 1$/f 1 0 0 1 0 0 0.5 -1.5/' s.nff >ior2.nff
    expect nz "ior2.nff:9: index of refraction -1.5" "$bin/rt_render" ior2.nff --out x.png
    ;;
nff-duplicates)
    head -n 9 s.nff >dup.nff
    i=0
    while [ $i -lt 20 ]; do
        echo "s 0 0 0 1" >>dup.nff
        i=$((i + 1))
    done
    echo "s 0 0 0 1.5" >>dup.nff
    expect 0 "exact duplicate objects dropped: 19 .*2 primitives" "$bin/rt_render" dup.nff --out x.png --size 8x8
    ;;
nff-earclip)
    # One 100,000-vertex random star polygon (simple, about half its corners reflex):
    # seconds of ear clipping before, 40 of them over a minute.
    head -n 9 s.nff >big.nff
    awk 'BEGIN { srand(7); print "p 100000"; for (i = 0; i < 100000; i++) { a = 6.283185307 * i / 100000; r = 0.5 + rand(); print r * cos(a), r * sin(a), 0 } }' >>big.nff
    expect nz "big.nff:10: concave polygon with 100000 vertices: .*ear clipping" \
        "$bin/rt_render" big.nff --out x.png --size 8x8
    ;;
obj-face256)
    {
        awk 'BEGIN { for (i = 0; i < 259; i++) printf "v %g %g 0\n", cos(i * 6.283185307 / 259), sin(i * 6.283185307 / 259) }'
        printf 'f'
        i=1
        while [ $i -le 259 ]; do
            printf ' %d' $i
            i=$((i + 1))
        done
        printf '\nf 1 2 3 4\n'
    } >big.obj
    expect nz "big.obj:260: face with 259 vertices: at most 255" "$bin/rt_render" big.obj --out x.png --size 8x8
    ;;
obj-duplicates)
    printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\n' >dup.obj
    i=0
    while [ $i -lt 30 ]; do
        echo "f 1 2 3" >>dup.obj
        i=$((i + 1))
    done
    echo "f 1 4 3" >>dup.obj # the same corners through another vertex record
    expect 0 "exact duplicate triangles dropped: 30 .*1 primitives" "$bin/rt_render" dup.obj --out x.png --size 8x8
    ;;
obj-map-kd)
    printf 'mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n' >t.obj
    printf 'newmtl red\nKd 1 0 0\nmap_Kd nowhere.png\n' >m.mtl
    expect 0 "materials naming a map_Kd texture: 1 \(the first: 'nowhere.png', which does not exist\)" \
        "$bin/rt_render" t.obj --out x.png --size 8x8
    ;;
mtl-per-scene)
    # Eight .mtl files of 3 MB each: each within 16 MB, together over it.
    : >t.obj
    i=0
    while [ $i -lt 8 ]; do
        awk -v k=$i 'BEGIN { for (j = 0; j < 1000; j++) printf "newmtl m%d_%d\nKd 0.5 0.5 0.5\n", k, j;
            for (j = 0; j < 100000; j++) print "# padding padding padding" }' >m$i.mtl
        echo "mtllib m$i.mtl" >>t.obj
        i=$((i + 1))
    done
    printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >>t.obj
    expect nz "16 MB for all the scene's .mtl files together" "$bin/rt_render" t.obj --out x.png --size 8x8
    awk 'BEGIN { for (j = 0; j < 10001; j++) printf "newmtl m%d\nKd 0.5 0.5 0.5\n", j }' >many.mtl
    printf 'mtllib many.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >many.obj
    expect nz "many.mtl:20001: more than 10000 materials" "$bin/rt_render" many.obj --out x.png --size 8x8
    ;;
lab07-headless-fail)
    # A scene the lab cannot load: the headless run exits non-zero, with no picture.
    printf 'nonsense\n' >bad.nff
    expect nz "bad.nff:1: unknown command" "$bin/lab07-raytrace" --headless --scene bad.nff --out bad.png --size 8x8
    [ -e bad.png ] && fail "wrote a picture of another scene"
    ;;
*)
    fail "unknown case"
    ;;
esac
echo "PASS ($case_)"
