#!/bin/busybox sh
# SPDX-License-Identifier: MIT
# /init of the MCP2210 test VM (see run_vm.sh). Each phase starts the model
# on /dev/uhid, waits for its hidraw node, runs the real zspan-mcp2210
# (hidapi, hidraw backend) against it, then stops the model, which dumps the
# panel's picture to /dev/ttyS1.
/bin/busybox --install -s /bin
export PATH=/bin
export LD_LIBRARY_PATH=/lib/x86_64-linux-gnu:/usr/lib/x86_64-linux-gnu
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
for m in $(cat /modules.order); do
    insmod /lib/modules/$m || echo "ZSVM insmod $m failed"
done
echo "ZSVM booted: $(cat /proc/uptime)"

wait_hidraw() { # $1 = present|absent
    i=0
    while [ $i -lt 200 ]; do
        n=$(ls /sys/class/hidraw 2>/dev/null | wc -l)
        if [ "$1" = present ] && [ "$n" -gt 0 ] && ls /dev/hidraw* >/dev/null 2>&1; then return 0; fi
        if [ "$1" = absent ] && [ "$n" -eq 0 ]; then return 0; fi
        sleep 0.05
        i=$((i + 1))
    done
    echo "ZSVM hidraw did not become $1"
    return 1
}

phase() { # tag "model options" client options...
    tag=$1
    margs=$2
    shift 2
    wait_hidraw absent
    /bin/mcp2210-uhid --tag "$tag" --out /dev/ttyS1 $margs &
    mp=$!
    wait_hidraw present
    t0=$(cut -d' ' -f1 /proc/uptime)
    /bin/zspan-mcp2210 "$@"
    rc=$?
    t1=$(cut -d' ' -f1 /proc/uptime)
    echo "ZSVM phase $tag client rc=$rc uptime $t0 -> $t1"
    kill $mp 2>/dev/null
    wait $mp
}

# 1. Two demo frames, the second as a partial update: the panel shows frame 1.
phase full "" --frames 2 --partial
# 2. Busy answers (every 5th data report refused, 3 times in a row) and an
#    engine that is still shifting after the last bytes (2 busy polls).
phase busy "--busy-every 5 --busy-burst 3 --lag 2" --frames 1 --start 7
# 3. The device vanishes in the middle of the frame.
phase unplug "--disconnect-after 700" --frames 1
echo "ZSVM done"
poweroff -f
