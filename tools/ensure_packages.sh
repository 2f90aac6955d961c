#!/bin/sh
# Install the Debian packages fcs3d needs, when they are missing.
# Usage: tools/ensure_packages.sh package ...
# Installs only what is missing, and only as root (apt-get, non-interactive). Otherwise prints
# the missing packages and the command to install them, and fails.
missing=""
for p in "$@"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)
  case "$status" in
    *"install ok installed"*) ;;
    *) missing="$missing $p" ;;
  esac
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" != "0" ]; then
  echo "fcs3d needs these Debian packages, which are not installed:$missing" >&2
  echo "Install them as root with:" >&2
  echo "  apt-get install -y --no-install-recommends$missing" >&2
  exit 1
fi
echo "Installing missing Debian packages:$missing"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q >/dev/null || { echo "apt-get update failed" >&2; exit 1; }
# shellcheck disable=SC2086
apt-get install -y -q --no-install-recommends $missing >/dev/null || {
  echo "apt-get install failed for:$missing" >&2; exit 1; }
echo "Installed:$missing"
