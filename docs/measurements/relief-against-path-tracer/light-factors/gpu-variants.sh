#!/bin/bash
# SPDX-License-Identifier: BSD-3-Clause
# The relief's GPU image at one ray and 2 x 2 per pixel, each rendered twice with the whole
# process timed, against the references of a scripts/bench-vlf-relief.sh run (see commands.txt).
# Usage: gpu-variants.sh VARIANT -> $OUTROOT/VARIANT/{map}-{gpu,gpu-2x2}.exr, times.txt, ab.csv
# Environment: BIN (mesolight), RUN (the benchmark's output directory), FIELD, OUTROOT, CAMERA and
# FOV (the office's view unless given; the Cornell box: CAMERA=278,273,-800,278,273,0 FOV=39.3077).
set -e
v=$1; out=${OUTROOT:-/tmp/walls/ab}/$v; mkdir -p $out; cd $out
bin=${BIN:-/work/main/build/bin/mesolight}
run=${RUN:-/tmp/walls/run}; field=${FIELD:-$run/props16-2049-72.vlf}
view=(--camera ${CAMERA:-4.6,1.6,4.8,2.2,0.8,1.2} --fov ${FOV:-65})
for name in procedural-bricks redeclipse-bricks; do
  if [ $name = procedural-bricks ]; then depth=$run/input/bricks-depth.pgm; else depth=$run/input/redeclipse-bricks-depth.png; fi
  for rep in 1 2; do
  for s in 1 2; do
    tag=gpu; extra=(); [ $s = 2 ] && { tag=gpu-2x2; extra=(--supersampling 2); }
    /usr/bin/time -f "$name $tag rep$rep wall %e s user %U s" -a -o times.txt bash /work/main/scripts/xvfb.sh $bin vlf render $field --mode progressive --relief back=$depth --relief-depth-scale 0.05 "${extra[@]}" "${view[@]}" --size 256x256 --out $name-$tag.png --exr $name-$tag.exr --force > $name-$tag.log 2>&1
  done; done
  for tag in gpu gpu-2x2; do
    $bin bench vlf-relief --reference $run/$name-reference.exr --reference-2 $run/$name-reference-2.exr --mask $run/$name-mask.exr --images $tag=$name-$tag.exr,flat-wall=$run/$name-flat-wall.exr,one-light=$run/$name-one-light.exr --label ab-$v-$name-$tag --csv $out/ab.csv > $name-$tag-bench.log 2>&1 || true
  done
done
