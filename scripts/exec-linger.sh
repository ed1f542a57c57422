#!/bin/bash
# How long `mvn -q exec:java` lingers after Ctrl+Q closes the demo, with the developer tools opened
# and a screenshot saved first (a SwingWorker's idle thread once kept it 15 s). Needs an X display
# (e.g. Xvfb :87) and xdotool; run from the repository root after `mvn -q compile`.
#   DISPLAY=:87 scripts/exec-linger.sh
set -e
mvn -q -o exec:java > /dev/null 2>&1 &
pid=$!
for i in $(seq 1 120); do
  [ -n "$(xdotool search --name '^Trisect' 2>/dev/null | head -1)" ] && break
  sleep 0.5
done
sleep 4
xdotool mousemove 300 300 click 1
sleep 1
xdotool key F12
sleep 2
xdotool key ctrl+s
sleep 2
xdotool mousemove 300 300 click 1
sleep 1
t0=$(date +%s.%N)
xdotool key ctrl+q
wait $pid
t1=$(date +%s.%N)
echo "mvn exec:java ended $(echo "$t1 - $t0" | bc) s after Ctrl+Q"
