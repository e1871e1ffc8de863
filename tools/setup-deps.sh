#!/usr/bin/env bash
# Install what the build needs from Debian, if missing (only when root;
# otherwise it lists what to install). Usage: tools/setup-deps.sh [extra packages...]
set -euo pipefail

want=(cmake gcc make pkg-config help2man libpng-dev libcairo2-dev libsndfile1-dev libcjson-dev libjansson-dev "$@")
missing=()
for p in "${want[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -eq 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq >/dev/null || true
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "setup: missing Debian packages: ${missing[*]}" >&2
  echo "setup: run as root, or: sudo apt-get install ${missing[*]}" >&2
  exit 1
fi
