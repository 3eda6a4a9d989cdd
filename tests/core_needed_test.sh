#!/usr/bin/env bash
# The core library links nothing beyond the C and C++ runtimes: its ELF
# NEEDED entries (readelf -d) name no third-party library.
set -euo pipefail
lib=$1
[[ -f $lib ]] || { echo "no such library: $lib"; exit 1; }
needed=$(readelf -d "$lib" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
echo "$lib needs: $(echo $needed)"
status=0
for n in $needed; do
  case $n in
    libstdc++.so.* | libm.so.* | libgcc_s.so.* | libc.so.* | libpthread.so.* | ld-linux*) ;;
    *) echo "third-party dependency: $n"; status=1 ;;
  esac
done
exit $status
