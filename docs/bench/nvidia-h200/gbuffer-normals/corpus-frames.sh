#!/usr/bin/env bash
# Every file of ../shared/corpus (carried as .corpus/corpus) rendered by main and by the change,
# 1280x720, the file's lights plus 4,096 generated ones, the visibility buffer with each raster
# and deferred, at the file's default view (Sponza and the gas station at each of their cameras):
# one line a frame, the HDR output of the change against main's. Run by the third call with
# ../record-steps.sh's variables (BASE: 'label:folder'; NEW: the folder, or 'label:folder');
# writes $OUT/corpus-frames.txt.
set -u
export LD_LIBRARY_PATH=$PWD/.devbin-lib
B=${BASE#*:} N=${NEW#*:}
T=$(mktemp -d)
find .corpus/corpus -name '*.gltf' -o -name '*.glb' | sort | while read -r file; do
  case $file in
  *Sponza.gltf) views='gltf:0 gltf:1 gltf:2 gltf:3' ;;
  *GasStation.gltf) views='gltf:0 gltf:1' ;;
  *) views=default ;;
  esac
  for view in $views; do
    camera=(); [ "$view" = default ] || camera=(--camera "$view")
    for method in 'visibility --vis-raster hardware' 'visibility --vis-raster compute' 'deferred'; do
      for build in base:$B new:$N; do
        ${build#*:}/manylights render --backend egl --scene "$file" "${camera[@]}" --size 1280x720 --lights 4096 \
          --method $method --out-float $T/${build%%:*}.pfm --out $T/${build%%:*}.png > $T/log 2>&1 \
          || { echo "$(basename "$file") $view $method ${build%%:*}: $(tail -1 $T/log)"; continue 2; }
      done
      echo "$(basename "$file") $view $method: $($N/manylights compare $T/base.pfm $T/new.pfm)"
    done
  done
done > $OUT/corpus-frames.txt
rm -rf "$T"
