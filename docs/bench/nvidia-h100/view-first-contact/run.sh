#!/bin/bash
# issue 25: view's frame rate under a carried Xvfb (Mesa's GLX on the server side, NVIDIA's on the
# client side), atrium and DamagedHelmet, 1280x720 and 2560x1440, default flags, panel shown.
D=$PWD/.dev-25
X=/tmp/x25
mkdir -p $X && for f in $D/debs/*.deb; do dpkg -x $f $X; done
export LD_LIBRARY_PATH=$D/lib:$X/usr/lib/x86_64-linux-gnu
export LIBGL_DRIVERS_PATH=$X/usr/lib/x86_64-linux-gnu/dri
[ -e /usr/bin/xkbcomp ] || cp $X/usr/bin/xkbcomp /usr/bin/xkbcomp   # Xvfb runs it from its compiled-in path
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv > $OUT/gpu.txt
nvidia-smi --query-gpu=timestamp,clocks.sm,utilization.gpu --format=csv -lms 500 > $OUT/smclock.csv &
SMI=$!
$X/usr/bin/Xvfb :25 -screen 0 2600x1500x24 -xkbdir $X/usr/share/X11/xkb -nolisten tcp > $OUT/xvfb.log 2>&1 &
XVFB=$!
sleep 3
export DISPLAY=:25 __GLX_VENDOR_LIBRARY_NAME=nvidia
H=$D/corpus/DamagedHelmet/glTF/DamagedHelmet.gltf
for size in 1280x720 2560x1440; do
  for scene in atrium $H; do
    echo "== $scene $size" | tee -a $OUT/view.txt
    timeout 60 $D/manylights view --scene $scene --size $size --run-for 10 --time --verbose >> $OUT/view.txt 2>&1
    echo "rc=$?" >> $OUT/view.txt
  done
done
timeout 60 $D/manylights view --scene $H --size 1280x720 --frames 3 --screenshot-window $OUT/helmet-window.png >> $OUT/view.txt 2>&1
kill $XVFB $SMI
grep -E "==|view:|GL_RENDERER|rc=|error|warning: the window" $OUT/view.txt
