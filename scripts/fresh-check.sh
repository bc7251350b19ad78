#!/usr/bin/env bash
# The README's two commands on a fresh Debian 12, timed: builds a minimal root with debootstrap
# from this machine's own apt sources, clones this repository's HEAD into it, and runs
# `bash scripts/run.sh` (no display: headless frames), then `bash scripts/test.sh` there, as root.
# Prints each command's wall time; the root is left in DIR for a look (remove it with rm -rf).
# Usage (as root): bash scripts/fresh-check.sh [DIR (default /tmp/stepwise-fresh)] [run|test|both (default both)]
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=${1:-/tmp/stepwise-fresh}
WHAT=${2:-both}
[ "$(id -u)" = 0 ] || { echo "fresh-check: run as root (debootstrap and chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || { apt-get update -qq; DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null; }

# The mirror this machine installs from (deb822 sources or a sources.list line).
mirror=$(grep -hoE '^URIs: *http[^ ]*/debian/?$' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -1 | sed 's/^URIs: *//')
[ -n "$mirror" ] || mirror=$(grep -hoE '^deb +http[^ ]*/debian/? +bookworm' /etc/apt/sources.list 2>/dev/null | head -1 | awk '{print $2}')
[ -n "$mirror" ] || { echo "fresh-check: no Debian mirror found in this machine's apt sources" >&2; exit 2; }

unmount() { for m in dev/shm dev/pts dev proc sys; do mountpoint -q "$ROOT/$m" && umount -l "$ROOT/$m"; done; true; }
trap unmount EXIT
if [ ! -f "$ROOT/etc/debian_version" ]; then
  start=$SECONDS
  debootstrap --variant=minbase bookworm "$ROOT" "$mirror" >"$ROOT.debootstrap.log" 2>&1 ||
    { tail -20 "$ROOT.debootstrap.log"; exit 1; }
  echo "fresh-check: debootstrap of bookworm from $mirror in $((SECONDS - start)) s"
fi
# A fresh machine has these: the kernel's filesystems, a /dev/shm, DNS, and the /etc/hosts that
# Debian's installer writes (debootstrap does not; without it 'localhost' does not resolve).
mount -t proc proc "$ROOT/proc"
mount --rbind /sys "$ROOT/sys"
mount --rbind /dev "$ROOT/dev"
mountpoint -q "$ROOT/dev/shm" || mount -t tmpfs shm "$ROOT/dev/shm"
cp /etc/resolv.conf "$ROOT/etc/resolv.conf"
[ -f "$ROOT/etc/hosts" ] || printf '127.0.0.1\tlocalhost\n::1\tlocalhost ip6-localhost ip6-loopback\n' >"$ROOT/etc/hosts"
# The repository as a clone of HEAD, the way a student gets it (git is not in minbase: copy the clone in).
rm -rf "$ROOT/root/stepwise"
git clone -q --no-hardlinks "$PWD" "$ROOT/root/stepwise"

run_in_root() {  # name command
  local start=$SECONDS
  if chroot "$ROOT" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin TERM=dumb bash -c "cd /root/stepwise && $2" \
      >"$ROOT.$1.log" 2>&1; then
    echo "fresh-check: $1 ($2) passed in $((SECONDS - start)) s; log $ROOT.$1.log"
  else
    echo "fresh-check: $1 ($2) FAILED after $((SECONDS - start)) s; last lines of $ROOT.$1.log:"
    tail -15 "$ROOT.$1.log"
    return 1
  fi
}
status=0
if [ "$WHAT" != test ]; then run_in_root run "bash scripts/run.sh" || status=1; fi
if [ "$WHAT" != run ]; then run_in_root test "bash scripts/test.sh" || status=1; fi
exit $status
