#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# check-package-metadata: the plain-metadata files parse and agree with VERSION:
# library.properties, library.json, idf_component.yml (ESP-IDF), zephyr/module.yml
# (Zephyr), CMakeLists.txt (reads VERSION), zspan.pc (make install). What they
# describe is only build-tested where README.md says so.
set -u
python3 - <<'PY'
import json, os, re, sys
import yaml
bad = []
version = open("VERSION").read().strip()
if not re.fullmatch(r"\d+\.\d+\.\d+", version): bad.append("VERSION %r is not MAJOR.MINOR.PATCH" % version)
hdr = open("include/zspan/zspan.h").read()
m = re.search(r'#define ZSPAN_VERSION_STRING "([^"]+)"', hdr)
if not m or m.group(1) != version: bad.append("include/zspan/zspan.h ZSPAN_VERSION_STRING %r" % (m and m.group(1)))
props = dict(l.split("=", 1) for l in open("library.properties").read().splitlines() if "=" in l)
if props.get("version") != version: bad.append("library.properties version %r" % props.get("version"))
lj = json.load(open("library.json"))
if lj.get("version") != version: bad.append("library.json version %r" % lj.get("version"))
idf = yaml.safe_load(open("idf_component.yml"))
if not isinstance(idf, dict) or str(idf.get("version")) != version: bad.append("idf_component.yml version")
if not idf.get("description"): bad.append("idf_component.yml: no description")
zm = yaml.safe_load(open("zephyr/module.yml"))
b = (zm or {}).get("build", {})
if (zm or {}).get("name") != "zspan": bad.append("zephyr/module.yml: name")
if not os.path.isfile(os.path.join(b.get("cmake", "-"), "CMakeLists.txt")): bad.append("zephyr/module.yml: build.cmake has no CMakeLists.txt")
if not os.path.isfile(b.get("kconfig", "-")): bad.append("zephyr/module.yml: build.kconfig missing")
cm = open("CMakeLists.txt").read()
if "idf_component_register" not in cm or "VERSION" not in cm: bad.append("CMakeLists.txt: no ESP-IDF branch or VERSION")
for e in bad: print("check-package-metadata: FAIL:", e)
if not bad: print("check-package-metadata: ok: library.properties, library.json, idf_component.yml, zephyr/module.yml parse; versions ==", version)
sys.exit(1 if bad else 0)
PY
rc=$?
grep -q "^Version: $(cat VERSION)\$" build/zspan.pc 2>/dev/null || { [ -f build/zspan.pc ] && { echo "check-package-metadata: FAIL: build/zspan.pc version"; rc=1; }; }
exit $rc
