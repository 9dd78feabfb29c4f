#!/usr/bin/env bash
# Installs what scripts/detect_mediapipe needs: Debian's chromium, node + npm (Debian's, when
# there is no node at all) and tools/mediapipe's pinned npm packages. Does nothing when all are there.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tool="$root/tools/mediapipe"

missing=()
[ -x /usr/bin/chromium ] || missing+=(chromium)
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup-mediapipe: installing ${missing[*]} (apt)" >&2
  sudo=
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# npm ci only when package-lock.json changed since the last install, so that a machine that
# has run this once needs no network again.
stamp="$tool/node_modules/.simcap-lock.sha256"
want="$(sha256sum "$tool/package-lock.json" | cut -d' ' -f1)"
if [ "$(cat "$stamp" 2>/dev/null || true)" != "$want" ]; then
  echo "setup-mediapipe: npm ci in $tool" >&2
  (cd "$tool" && npm ci --no-audit --no-fund --loglevel=error)
  echo "$want" >"$stamp"
fi
