#!/usr/bin/env bash
# Builds the third-party libraries of the WebAssembly build (DESIGN.md §5c) with Debian's emscripten,
# from Debian's own source packages: GMP (+gmpxx), MPFR, Dear ImGui (the libimgui-dev version, with
# the GLFW and OpenGL3 backends) and md4c (+md4c-html). Installs into a cache outside the repository,
#   ${STEPWISE_WEB_CACHE:-/var/cache/stepwise-web}/{include,lib}
# with ImGui's headers under include/imgui/ as libimgui-dev lays them out (-I.../include/imgui).
# Header-only libraries (Boost, CGAL, nlohmann-json, stb, GLM, CLI11) are reused from the host packages.
# Idempotent: a library whose stamp (keyed by its source package version) and artefacts are present is
# skipped. Ends by compiling and running a test under node (GMP/gmpxx, MPFR, ImGui, md4c): exits non-zero
# unless it prints OK. Runs as root on Debian 12. Usage: scripts/web-deps.sh
set -euo pipefail

PREFIX=${STEPWISE_WEB_CACHE:-/var/cache/stepwise-web}
WORK=$PREFIX/src          # extracted sources and their build logs
STAMPS=$PREFIX/stamps
JOBS=$(nproc)
SRC_LIST=/etc/apt/sources.list.d/stepwise-src.sources
SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
say() { echo "web-deps: $*"; }

# --- 1. Packages (only those missing) ------------------------------------------------------------------
PACKAGES=(
  emscripten nodejs dpkg-dev xz-utils build-essential m4
  libimgui-dev libboost-dev libcgal-dev nlohmann-json3-dev libstb-dev libglm-dev libcli11-dev
  libcgal-demo fonts-dejavu-core cmake  # the meshes and fonts the page embeds; the build itself
)
source "$(dirname "$0")/packages.sh"
install_missing "${PACKAGES[@]}"

# --- 2. deb-src entries, derived from the machine's own Debian entries -----------------------------------
# Copies every enabled "deb" entry whose suite is this release's (codename, -updates, -security,
# -backports) as "deb-src"; third-party repositories (other suites) are left out, so the update below
# cannot fail on them. Skipped when the machine already has deb-src entries of its own.
CODENAME=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
derive_deb_src() {
  local f
  # deb822 files (*.sources)
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -e "$f" ] && [ "$f" != "$SRC_LIST" ] || continue
    cat "$f"; printf '\n'
  done | awk -v cn="$CODENAME" '
    function suiteok(s) { return s ~ ("^" cn "([-/](updates|security|backports))?$") }
    function flush(   i, out, k, ss) {
      if (types ~ /(^|[ \t])deb([ \t]|$)/ && enabled !~ /^[ \t]*[Nn][Oo]/ && nf) {
        out = ""; k = split(suites, ss, /[ \t]+/)
        for (i = 1; i <= k; i++) if (ss[i] != "" && suiteok(ss[i])) out = out " " ss[i]
        if (out != "") {
          print "Types: deb-src"
          for (i = 1; i <= nf; i++) print (keys[i] == "suites" ? "Suites:" out : lines[i])
          print ""
        }
      }
      types = ""; suites = ""; enabled = ""; nf = 0
    }
    /^[ \t]*#/ { next }
    /^[ \t]*$/ { flush(); next }
    /^[ \t]/   { if (nf) lines[nf] = lines[nf] "\n" $0; next }
    {
      key = tolower($0); sub(/:.*/, "", key); val = $0; sub(/^[^:]*:[ \t]*/, "", val)
      if (key == "types") { types = val; next }
      if (key == "suites") suites = val
      if (key == "enabled") enabled = val
      keys[++nf] = key; lines[nf] = $0
    }
    END { flush() }'
  # one-line files (sources.list, *.list)
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -e "$f" ] || continue
    cat "$f"
  done | awk -v cn="$CODENAME" '
    $1 != "deb" { next }
    {
      i = 2; opts = ""
      if ($2 ~ /^\[/) { while (i <= NF) { opts = opts " " $i; if ($i ~ /\]$/) { i++; break } i++ } }
      uri = $i; suite = $(i + 1); comps = ""
      for (j = i + 2; j <= NF && $j !~ /^#/; j++) comps = comps " " $j
      if (suite !~ ("^" cn "([-/](updates|security|backports))?$")) next
      print "Types: deb-src"; print "URIs: " uri; print "Suites: " suite; print "Components:" comps
      gsub(/[\[\]]/, "", opts); n = split(opts, o, /[ \t]+/)
      for (k = 1; k <= n; k++) {
        split(o[k], kv, "=")
        if (kv[1] == "signed-by") print "Signed-By: " kv[2]
        else if (kv[1] == "arch") print "Architectures: " kv[2]
        else if (kv[1] == "trusted") print "Trusted: " kv[2]
      }
      print ""
    }'
}
has_own_deb_src() {
  local f
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
    [ -e "$f" ] && [ "$f" != "$SRC_LIST" ] || continue
    grep -Eq '^[[:space:]]*(deb-src[[:space:]]|Types:.*deb-src)' "$f" && return 0
  done
  return 1
}
if ! has_own_deb_src; then
  entries=$(derive_deb_src)
  [ -n "$entries" ] || { say "no Debian '$CODENAME' entry in the apt sources to derive deb-src from"; exit 1; }
  entries="# Written by stepwise scripts/web-deps.sh: the deb-src twins of this machine's Debian entries.
$entries"
  if [ "$(cat "$SRC_LIST" 2>/dev/null)" != "$entries" ]; then
    say "writing $SRC_LIST"
    printf '%s\n' "$entries" | $SUDO tee "$SRC_LIST" >/dev/null
    rm -f "$PREFIX/.src-updated"
  fi
fi
if ! apt-cache showsrc gmp 2>/dev/null | grep '^Package: gmp$' >/dev/null; then  # grep reads it all (-q would close the pipe early)
  say "fetching the source indexes"
  if [ -e "$SRC_LIST" ]; then   # only the deb-src entries: other repositories are not touched
    $SUDO apt-get update -qq -o Dir::Etc::SourceList="$SRC_LIST" -o Dir::Etc::SourceParts=/nonexistent \
      -o APT::Get::List-Cleanup=0
  else
    $SUDO apt-get update -qq
  fi
fi

# --- 3. emscripten's environment ------------------------------------------------------------------------
# Debian's node module folder, for emscripten's optimizer (node-acorn) under a non-Debian node.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
# Debian ships a prebuilt, frozen system-library cache; it is used as is (offline). Only if it cannot be
# written (its lock file) is a copy made under the cache prefix.
EM_PKG_CACHE=/usr/share/emscripten/cache
if [ -z "${EM_CACHE:-}" ] && [ ! -w "$EM_PKG_CACHE" ]; then
  export EM_CACHE=$PREFIX/em-cache
  [ -d "$EM_CACHE/sysroot" ] || { mkdir -p "$EM_CACHE"; cp -a "$EM_PKG_CACHE/." "$EM_CACHE/"; }
fi
mkdir -p "$PREFIX/include" "$PREFIX/lib" "$WORK" "$STAMPS" "$PREFIX/test"
emcc --version | sed -n 1p  # sed reads it all: head would close the pipe under emcc (BrokenPipeError)

# --- helpers ----------------------------------------------------------------------------------------------
# src_version NAME[=VERSION]: the Debian version of the source package apt-get source would fetch.
src_version() {
  local name=${1%%=*} dsc
  dsc=$(apt-get source --print-uris -qq "$1" | awk '$2 ~ /\.dsc$/ { print $2; exit }')
  [ -n "$dsc" ] || { say "no source package for $1"; exit 1; }
  dsc=${dsc#"${name}_"}; echo "${dsc%.dsc}"
}
# fresh_source NAME[=VERSION]: extract (patched) into $WORK/NAME; prints the source tree's path.
# A mirror may lack a package's Debian diff (.debian.tar.*: seen for md4c 0.4.8-1) while apt fetched
# and verified its upstream tarball: then the upstream tarball of that version is built as is, and said so.
fresh_source() {
  local name=${1%%=*} dir=$WORK/${1%%=*} orig
  rm -rf "$dir"; mkdir -p "$dir"
  if ! (cd "$dir" && apt-get source -q "$1" >"$dir/source.log" 2>&1); then
    orig=$(find "$dir" -maxdepth 1 -name '*.orig.tar.*' ! -name '*.asc' -print -quit)
    if [ -n "$orig" ] && grep -q 'Failed to fetch .*\.debian\.tar\.' "$dir/source.log"; then
      say "$name: $(grep -m1 -o 'Failed to fetch .*' "$dir/source.log")" >&2
      say "$name: building the upstream tarball $(basename "$orig") without Debian's patches" >&2
      mkdir "$dir/$name-upstream"; tar -xf "$orig" -C "$dir/$name-upstream" --strip-components=1
    else
      cat "$dir/source.log" >&2; exit 1
    fi
  fi
  find "$dir" -mindepth 1 -maxdepth 1 -type d -print -quit
}
# built NAME VERSION ARTEFACT...: true when the stamp says VERSION and every artefact exists.
built() {
  local name=$1 ver=$2 a; shift 2
  [ "$(cat "$STAMPS/$name" 2>/dev/null)" = "$ver" ] || return 1
  for a in "$@"; do [ -e "$PREFIX/$a" ] || return 1; done
}
# logged LOG CMD...: runs CMD with its output in LOG; on failure shows the log's tail and stops.
logged() {
  local log=$1; shift
  "$@" >>"$log" 2>&1 || { echo "web-deps: FAILED: $*  (log: $log)"; tail -40 "$log"; exit 1; }
}
elapsed() { printf '%dm%02ds' $(($1 / 60)) $(($1 % 60)); }
TIMES=()
T0=$SECONDS

# --- 4. GMP (+ gmpxx) -------------------------------------------------------------------------------------
ver=$(src_version gmp)
if built gmp "$ver" lib/libgmp.a lib/libgmpxx.a include/gmp.h include/gmpxx.h; then
  say "gmp $ver: cached"
else
  say "gmp $ver: building (slow: ~15 min on two loaded cores)"; t=$SECONDS
  src=$(fresh_source gmp); log=$WORK/gmp/build.log
  # Debian's repacked (dfsg) source has no doc/, which config.status still generates: a stub.
  if [ ! -e "$src/doc/Makefile.in" ]; then
    mkdir -p "$src/doc"
    printf '%s:\n\t@:\n.PHONY: %s\n' \
      "all install install-data install-exec uninstall check installcheck clean distclean mostlyclean maintainer-clean info dvi pdf ps html install-info install-dvi install-pdf install-ps install-html tags ctags distdir" \
      "all" >"$src/doc/Makefile.in"
  fi
  cd "$src"
  logged "$log" emconfigure ./configure --host=none --disable-assembly --enable-cxx --disable-shared \
    --enable-static --prefix="$PREFIX" CFLAGS=-O2 CXXFLAGS=-O2
  logged "$log" nice emmake make -j"$JOBS"
  logged "$log" emmake make install
  echo "$ver" >"$STAMPS/gmp"
  TIMES+=("gmp $(elapsed $((SECONDS - t)))"); say "gmp: built in $(elapsed $((SECONDS - t)))"
fi

# --- 5. MPFR ----------------------------------------------------------------------------------------------
ver=$(src_version mpfr4)
if built mpfr4 "$ver-gmp$(cat "$STAMPS/gmp")-fp" lib/libmpfr.a include/mpfr.h; then
  say "mpfr4 $ver: cached"
else
  say "mpfr4 $ver: building"; t=$SECONDS
  src=$(fresh_source mpfr4); log=$WORK/mpfr4/build.log
  # Cross-compiling, MPFR's configure cannot run its floating-point probes and falls back to "format
  # unknown, no subnormals, no signed zeros, add -ffloat-store" (correct but slower paths). The same
  # facts, measured here under node, are handed to it as its cache variables.
  cat >"$WORK/mpfr4/fp-probe.c" <<'PROBE'
#include <float.h>
#include <stdio.h>
int main(void) {
  volatile double x = 2.22507385850720138309e-308, y = x / 2.0, z = 0.0;
  volatile float fx = 1.17549435e-38f, fy = fx / 2.0f;
  union { double v; unsigned char b[sizeof(double)]; } d = { 1.0 };
  union { long double v; unsigned char b[sizeof(long double)]; } l = { 1.0L };
  int dle = sizeof d.b == 8 && DBL_MANT_DIG == 53 && d.b[7] == 0x3f && d.b[6] == 0xf0;
  int qle = sizeof l.b == 16 && LDBL_MANT_DIG == 113 && l.b[15] == 0x3f && l.b[14] == 0xff;
  printf("mpfr_cv_c_double_format=%s\n", dle ? "IEEE double, little endian" : "unknown");
  printf("mpfr_cv_c_long_double_format=%s\n", qle ? "IEEE quad, little endian" : "unknown");
  printf("mpfr_cv_have_subnorm_dbl=%s\n", y != 0 && 2.0 * y == x ? "yes" : "no");
  printf("mpfr_cv_have_subnorm_flt=%s\n", fy != 0 && 2.0f * fy == fx ? "yes" : "no");
  printf("mpfr_cv_have_signedz=%s\n", 1.0 / z != 1.0 / -z ? "yes" : "no");
  printf("mpfr_cv_gcc_floatconv_bug=%s\n", FLT_EVAL_METHOD == 0 ? "no" : "yes, use -ffloat-store");
  return 0;
}
PROBE
  logged "$log" emcc -O0 -sSINGLE_FILE=1 "$WORK/mpfr4/fp-probe.c" -o "$WORK/mpfr4/fp-probe.js"
  mapfile -t fpfacts < <(node "$WORK/mpfr4/fp-probe.js")
  ((${#fpfacts[@]} == 6)) || { say "mpfr4: the floating-point probe failed under node"; exit 1; }
  printf '  %s\n' "${fpfacts[@]}" | tee -a "$log"
  cd "$src"
  logged "$log" emconfigure ./configure --host=wasm32-unknown-emscripten --with-gmp="$PREFIX" \
    --disable-shared --enable-static --disable-thread-safe --disable-float128 --disable-decimal-float \
    --prefix="$PREFIX" CFLAGS=-O2 "${fpfacts[@]}"
  logged "$log" nice emmake make -j"$JOBS"
  logged "$log" emmake make install
  echo "$ver-gmp$(cat "$STAMPS/gmp")-fp" >"$STAMPS/mpfr4"
  TIMES+=("mpfr4 $(elapsed $((SECONDS - t)))"); say "mpfr4: built in $(elapsed $((SECONDS - t)))"
fi

# --- 6. Dear ImGui: the version of the host's libimgui-dev --------------------------------------------------
imgui_src_ver=$(dpkg-query -W -f='${source:Version}' libimgui-dev)
ver=$(src_version "imgui=$imgui_src_ver")
[ "${ver%%-*}" = "$(dpkg-query -W -f='${Version}' libimgui-dev | sed 's/^[0-9]*://; s/-[^-]*$//')" ] ||
  { say "imgui source $ver does not match libimgui-dev $(dpkg-query -W -f='${Version}' libimgui-dev)"; exit 1; }
# The OpenGL3 backend for WebGL 2 (GLSL ES 3.00), not ImGui's emscripten default, WebGL 1; and 32-bit
# vertex indices: WebGL has no base vertex, so a draw list of more than 65,536 vertices (a 3D view of a
# mesh) needs them (visualizer/web/dependencies.cmake defines the same for the app).
ver=$ver-es3-idx32
if built imgui "$ver" lib/libimgui.a include/imgui/imgui.h include/imgui/backends/imgui_impl_glfw.h; then
  say "imgui $ver: cached"
else
  say "imgui $ver: building"; t=$SECONDS
  src=$(fresh_source "imgui=$imgui_src_ver"); log=$WORK/imgui/build.log
  obj=$WORK/imgui/obj; mkdir -p "$obj"; cd "$src"
  units=(imgui.cpp imgui_draw.cpp imgui_tables.cpp imgui_widgets.cpp imgui_demo.cpp
         misc/cpp/imgui_stdlib.cpp backends/imgui_impl_glfw.cpp backends/imgui_impl_opengl3.cpp)
  export IMGUI_SRC=$src IMGUI_OBJ=$obj
  logged "$log" nice xargs -P"$JOBS" -I{} sh -ec \
    'u={}; em++ -O2 -std=c++17 -sUSE_GLFW=3 -DIMGUI_IMPL_OPENGL_ES3 "-DImDrawIdx=unsigned int" -I"$IMGUI_SRC" -I"$IMGUI_SRC/backends" -c "$IMGUI_SRC/$u" \
       -o "$IMGUI_OBJ/$(basename "$u" .cpp).o"' < <(printf '%s\n' "${units[@]}")
  rm -f "$PREFIX/lib/libimgui.a"
  logged "$log" emar rcs "$PREFIX/lib/libimgui.a" "$obj"/*.o
  # Headers as libimgui-dev lays them out: /usr/include/imgui/{imgui.h,...,backends/*.h}.
  rm -rf "$PREFIX/include/imgui"; mkdir -p "$PREFIX/include/imgui/backends"
  cp imconfig.h imgui.h imgui_internal.h imstb_rectpack.h imstb_textedit.h imstb_truetype.h \
     misc/cpp/imgui_stdlib.h "$PREFIX/include/imgui/"
  cp backends/imgui_impl_glfw.h backends/imgui_impl_opengl3.h backends/imgui_impl_opengl3_loader.h \
     "$PREFIX/include/imgui/backends/"
  mkdir -p "$PREFIX/lib/pkgconfig"
  printf 'prefix=%s\nincludedir=${prefix}/include/imgui\nlibdir=${prefix}/lib\n\nName: imgui\nDescription: Dear ImGui (wasm)\nVersion: %s\nLibs: -L${libdir} -limgui\nCflags: -I${includedir}\n' \
    "$PREFIX" "${ver%%+*}" >"$PREFIX/lib/pkgconfig/imgui.pc"
  echo "$ver" >"$STAMPS/imgui"
  TIMES+=("imgui $(elapsed $((SECONDS - t)))"); say "imgui: built in $(elapsed $((SECONDS - t)))"
fi

# --- 7. md4c (+ md4c-html) --------------------------------------------------------------------------------
ver=$(src_version md4c)
if built md4c "$ver" lib/libmd4c.a lib/libmd4c-html.a include/md4c.h include/md4c-html.h; then
  say "md4c $ver: cached"
else
  say "md4c $ver: building"; t=$SECONDS
  src=$(fresh_source md4c); log=$WORK/md4c/build.log
  obj=$WORK/md4c/obj; mkdir -p "$obj"; cd "$src/src"
  for u in md4c md4c-html entity; do   # as md4c's CMakeLists: md4c.c with MD4C_USE_UTF8
    logged "$log" emcc -O2 $([ $u = md4c ] && echo -DMD4C_USE_UTF8) -I. -c "$u.c" -o "$obj/$u.o"
  done
  rm -f "$PREFIX/lib/libmd4c.a" "$PREFIX/lib/libmd4c-html.a"
  logged "$log" emar rcs "$PREFIX/lib/libmd4c.a" "$obj/md4c.o"
  logged "$log" emar rcs "$PREFIX/lib/libmd4c-html.a" "$obj/md4c-html.o" "$obj/entity.o"
  cp md4c.h md4c-html.h "$PREFIX/include/"
  echo "$ver" >"$STAMPS/md4c"
  TIMES+=("md4c $(elapsed $((SECONDS - t)))"); say "md4c: built in $(elapsed $((SECONDS - t)))"
fi

# --- 8. Proof: compile, link and run under node ---------------------------------------------------------------
t=$SECONDS
TEST=$PREFIX/test
cat >"$TEST/web-deps-test.cpp" <<'EOF'
// Written by scripts/web-deps.sh: the wasm libraries compute right under node.
#include <gmpxx.h>
#include <mpfr.h>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <md4c.h>
#include <md4c-html.h>
#include <cstdio>
#include <cstring>
#include <string>

static int fails = 0;
static void check(bool ok, const char* what) { std::printf("%s %s\n", ok ? "ok  " : "FAIL", what); fails += !ok; }

int main() {
  // GMP: exact rationals and a 200-digit product.
  mpq_class q = mpq_class(1, 3) + mpq_class(1, 6);
  check(q == mpq_class(1, 2) && q.get_str() == "1/2", "gmpxx: 1/3 + 1/6 == 1/2");
  mpz_class ten100; mpz_ui_pow_ui(ten100.get_mpz_t(), 10, 100);
  mpz_class p = (ten100 + 1) * (ten100 - 1);  // 10^200 - 1: two hundred nines
  check(p.get_str() == std::string(200, '9'), "gmpxx: (10^100+1)(10^100-1) == 10^200-1 (200 digits)");
  mpz_class f = 1; for (int i = 2; i <= 100; ++i) f *= i;  // 100! has 158 digits, 24 trailing zeros
  std::string fs = f.get_str();
  check(fs.size() == 158 && fs.rfind("933262154439441526816992388562667004907", 0) == 0, "gmpxx: 100!");
  // MPFR: sqrt(2) to 300 bits.
  mpfr_t r; mpfr_init2(r, 300); mpfr_sqrt_ui(r, 2, MPFR_RNDN);  // 300 bits: 90 significant digits
  mpfr_exp_t e; char* d = mpfr_get_str(nullptr, &e, 10, 90, r, MPFR_RNDN); mpfr_clear(r);
  check(e == 1 && std::strncmp(d, "1414213562373095048801688724209698078569671875376948073176679737990732478462107038850387", 88) == 0,
        "mpfr: sqrt(2) to 300 bits, 88 leading digits");
  mpfr_free_str(d);
  mpfr_t z; mpfr_init2(z, 53); mpfr_set_d(z, -0.0, MPFR_RNDN); bool negzero = mpfr_signbit(z);
  mpfr_set_ui_2exp(z, 3, -1074, MPFR_RNDN); double sub = mpfr_get_d(z, MPFR_RNDN); mpfr_clear(z);
  check(negzero && sub == 3 * 4.9406564584124654e-324, "mpfr: -0.0 and subnormal doubles round-trip");
  // ImGui: one headless frame.
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO(); io.DisplaySize = ImVec2(320, 240); io.DeltaTime = 1.0f / 60;
  unsigned char* px; int w, h; io.Fonts->GetTexDataAsRGBA32(&px, &w, &h);
  std::string s = "edit";
  for (int frame = 0; frame < 2; ++frame) {  // a new auto-sized window is hidden on its first frame
    ImGui::NewFrame(); ImGui::Begin("web"); ImGui::Text("%s", IMGUI_VERSION);
    ImGui::InputText("s", &s); ImGui::End(); ImGui::Render();
  }
  check(ImGui::GetDrawData()->TotalVtxCount > 0 && std::strcmp(IMGUI_VERSION, "1.86") == 0, "imgui 1.86: headless frames drawn");
  ImGui::DestroyContext();
  // md4c: Markdown to HTML.
  std::string html, md = "# Title\n\n*x* `y`\n";
  md_html(md.data(), (MD_SIZE)md.size(), [](const MD_CHAR* t, MD_SIZE n, void* u) { ((std::string*)u)->append(t, n); },
          &html, MD_DIALECT_GITHUB, 0);
  check(html.find("<h1>Title</h1>") != std::string::npos && html.find("<em>x</em>") != std::string::npos, "md4c-html");
  std::puts(fails ? "FAILED" : "OK");
  return fails != 0;
}
EOF
# The GLFW and OpenGL3 backends: compiled and linked (they need a browser to run).
cat >"$TEST/web-deps-backends.cpp" <<'EOF'
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <GLFW/glfw3.h>
int main() {
  if (!glfwInit()) return 1;
  GLFWwindow* w = glfwCreateWindow(64, 64, "t", nullptr, nullptr);
  ImGui::CreateContext();
  bool ok = w && ImGui_ImplGlfw_InitForOpenGL(w, true) && ImGui_ImplOpenGL3_Init("#version 300 es");
  return ok ? 0 : 1;
}
EOF
INC=(-I"$PREFIX/include" -I"$PREFIX/include/imgui" "-DImDrawIdx=unsigned int")  # as ImGui was built
log=$TEST/test.log; : >"$log"
logged "$log" em++ -O2 -std=c++20 -sSINGLE_FILE=1 "${INC[@]}" "$TEST/web-deps-test.cpp" -L"$PREFIX/lib" \
  -lmpfr -lgmpxx -lgmp -limgui -lmd4c-html -lmd4c -o "$TEST/web-deps-test.js"
logged "$log" em++ -O2 -std=c++20 -sSINGLE_FILE=1 -sUSE_GLFW=3 -sMAX_WEBGL_VERSION=2 "${INC[@]}" \
  "$TEST/web-deps-backends.cpp" -L"$PREFIX/lib" -limgui -o "$TEST/web-deps-backends.js"
node "$TEST/web-deps-test.js" >>"$log" 2>&1 || true
sed -n '/^ok \|^FAIL\|^OK$\|^FAILED$/p' "$log"
[ "$(tail -1 "$log")" = OK ] || { say "the wasm test failed (log: $log)"; tail -20 "$log"; exit 1; }
say "test: built and ran in $(elapsed $((SECONDS - t)))"

((${#TIMES[@]})) && say "built: ${TIMES[*]}; total $(elapsed $((SECONDS - T0)))"
say "cache $PREFIX:"
(cd "$PREFIX/lib" && ls -l --block-size=K ./*.a | awk '{ print "  lib/" substr($NF, 3) "  " $5 }')
