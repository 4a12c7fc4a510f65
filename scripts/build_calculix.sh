#!/usr/bin/env bash
# CalculiX (ccx 2.20, Debian's calculix-ccx source) with interlock's thin-layer UMAT, in one
# command:
#
#     bash scripts/build_calculix.sh [BUILD_DIR]      (default: build-calculix/)
#
# prints, as its last line, the path of the binary, BUILD_DIR/bin/ccx_interlock.
#
# What it does (as root, or with sudo, on Debian 12; each step only when needed):
#  1. a deb-src entry, when the machine has none: derived from the machine's own apt sources
#     (deb822 /etc/apt/sources.list.d/*.sources with "Types: deb", or one-line "deb" entries),
#     written to /etc/apt/sources.list.d/interlock-deb-src.{sources,list}; no host is named
#     here;
#  2. the build dependencies (Debian's list for calculix-ccx: gfortran, libspooles-dev,
#     libarpack2-dev, liblapack-dev, libblas-dev, ...) and `apt-get source calculix-ccx` into
#     BUILD_DIR/src;
#  3. ccx's objects, compiled ONCE as Debian's package compiles them (debian/rules + ccx's
#     Makefile, Debian's patches applied), kept in BUILD_DIR/src: the binary is the stock ccx
#     with only the `umat` replaced (ccx's stub umat.o is left out of the link);
#  4. interlock's single-file bundle for CalculiX (scripts/make_bundle.py with the entry
#     umat/calculix/interlock_ccx_umat.f90: the library, the 2D law's body, the thin-layer
#     entry and ccx's `umat`), compiled and linked with ccx's objects. This step reruns when
#     the bundle's text changes (a change to src/ or umat/ relinks in seconds).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build-calculix}"
mkdir -p "$build"
build="$(cd "$build" && pwd)"
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
log() { echo "build_calculix: $*" >&2; }

# --- 1. deb-src entry, derived from the machine's own sources (only when there is none).
have_deb_src() {
  grep -qsE '^[[:space:]]*deb-src[[:space:]]' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null \
    || grep -qsiE '^[[:space:]]*Types:.*deb-src' /etc/apt/sources.list.d/*.sources 2>/dev/null
}
add_deb_src() {
  local tmp
  tmp="$(mktemp)"
  # deb822: every stanza whose Types has `deb` and no `deb-src`, with `Types: deb-src`.
  if ls /etc/apt/sources.list.d/*.sources > /dev/null 2>&1; then
    awk '
      function flush() { if (n > 0 && is_deb) { for (i = 1; i <= n; i++) print lines[i]; print "" } n = 0; is_deb = 0 }
      /^[[:space:]]*$/ { flush(); next }
      /^[[:space:]]*#/ { next }
      tolower($1) == "types:" { for (i = 2; i <= NF; i++) if ($i == "deb") is_deb = 1
                                lines[++n] = "Types: deb-src"; next }
      { lines[++n] = $0 }
      END { flush() }' /etc/apt/sources.list.d/*.sources > "$tmp"
    if [ -s "$tmp" ]; then
      $sudo_cmd install -m 644 "$tmp" /etc/apt/sources.list.d/interlock-deb-src.sources
      rm -f "$tmp"
      return
    fi
  fi
  # One-line format: every `deb` line as `deb-src`.
  cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null \
    | sed -n 's/^[[:space:]]*deb[[:space:]]/deb-src /p' > "$tmp" || true
  if [ ! -s "$tmp" ]; then
    rm -f "$tmp"
    log "no apt source to derive a deb-src entry from (no 'Types: deb' stanza, no 'deb' line)"
    exit 1
  fi
  $sudo_cmd install -m 644 "$tmp" /etc/apt/sources.list.d/interlock-deb-src.list
  rm -f "$tmp"
}

src="$build/src"
if [ ! -f "$src/.fetched" ]; then
  if ! have_deb_src; then
    log "adding a deb-src entry derived from this machine's apt sources"
    add_deb_src
  fi
  log "installing the build dependencies of calculix-ccx and fetching its source"
  $sudo_cmd apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get build-dep -y -qq -o DPkg::Lock::Timeout=600 calculix-ccx >&2
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends \
    -o DPkg::Lock::Timeout=600 dpkg-dev python3 gfortran >&2
  rm -rf "$src"
  mkdir -p "$src"
  (cd "$src" && apt-get source -qq calculix-ccx >&2)
  touch "$src/.fetched"
fi

# --- 2. ccx's objects, once, with Debian's flags (debian/rules: UPSTREAM_CFLAGS and
# UPSTREAM_FFLAGS plus dpkg-buildflags with hardening=+all; ccx's Makefile compiles every .f/.c
# into ccx_2.20.a and ccx_2.20.o).
ccx_src="$(ls -d "$src"/calculix-ccx-*/ccx_*/src | head -n 1)"
ccx_version="$(basename "$(dirname "$ccx_src")")"    # ccx_2.20
if [ ! -f "$ccx_src/.built" ]; then
  log "compiling $ccx_version as Debian's package does (once; a few minutes)"
  export DEB_BUILD_MAINT_OPTIONS=hardening=+all
  upstream_cflags='-Wall -I/usr/include/spooles -DARCH="Linux" -DSPOOLES -DARPACK -DMATRIXSTORAGE -DUSE_MT=1'
  cflags="$upstream_cflags $(dpkg-buildflags --get CFLAGS) $(dpkg-buildflags --get CPPFLAGS) $(dpkg-buildflags --get LDFLAGS)"
  fflags="-fallow-argument-mismatch $(dpkg-buildflags --get FFLAGS)"
  (cd "$ccx_src" && make -s -j "$(nproc 2>/dev/null || echo 2)" CFLAGS="$cflags" FFLAGS="$fflags" \
     "$ccx_version.a" "$ccx_version.o" > "$build/ccx_compile.log" 2>&1) || {
    tail -n 40 "$build/ccx_compile.log"; log "compiling ccx failed (log: $build/ccx_compile.log)"; exit 1; }
  # The stub umat.o defines `umat`, which ours replaces: an archive without it.
  cp "$ccx_src/$ccx_version.a" "$build/ccx_without_umat.a"
  ar d "$build/ccx_without_umat.a" umat.o
  printf '%s\n' "$(dpkg-buildflags --get LDFLAGS)" > "$build/ccx_ldflags"
  touch "$ccx_src/.built"
fi

# --- 3. interlock's bundle for ccx, compiled and linked only when its text changed.
mkdir -p "$build/interlock" "$build/bin"
bundle="$build/interlock/interlock_ccx_bundle.f90"
next="$build/interlock/interlock_ccx_bundle_next.f90"
python3 "$here/scripts/make_bundle.py" --source-dir "$here" \
  --entry umat/calculix/interlock_ccx_umat.f90 --output "$next" > /dev/null
binary="$build/bin/ccx_interlock"
if [ -x "$binary" ] && [ -f "$bundle" ] && cmp -s "$bundle" "$next"; then
  rm -f "$next"
else
  log "compiling interlock's thin-layer umat and linking $binary"
  (cd "$build/interlock" && gfortran -O2 -fopenmp -c "$next" -o interlock_ccx_bundle.o)
  # ccx's own link line (its Makefile: $(FC) -Wall -O2 -o $@ ccx_2.20.o ccx_2.20.a $(LIBS)
  # -fopenmp $(LDFLAGS)) with our umat before the archive without the stub.
  # shellcheck disable=SC2046
  gfortran -Wall -O2 -o "$binary.tmp" "$ccx_src/$ccx_version.o" "$build/interlock/interlock_ccx_bundle.o" \
    "$build/ccx_without_umat.a" -lspooles -lpthread -larpack -llapack -lblas -lm -lc -fopenmp \
    $(cat "$build/ccx_ldflags")
  mv "$binary.tmp" "$binary"
  mv "$next" "$bundle"     # last: an interrupted build relinks next time
fi
echo "$binary"
