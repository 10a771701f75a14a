#!/usr/bin/env bash
# Installs, from Debian's packages, whatever proxsim needs and this machine lacks.
# Idempotent and non-interactive; works as root or through sudo.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev libeigen3-dev libyaml-cpp-dev libassimp-dev libcli11-dev
  nlohmann-json3-dev librandom123-dev liburdfdom-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libbullet-dev libboost-dev   # Boost.Math (header-only) for the studies; MuJoCo comes from PyPI, into .venv/ below (python/requirements.txt)
  liboctomap-dev
  python3-matplotlib python3-numpy
  python3-dev pybind11-dev python3-pytest python3-venv
  libopenmpi-dev openmpi-bin
  slurm-wlm munge   # test only: the job-array test starts its own slurmctld + slurmd on localhost (tests/slurm/)
  nodejs npm   # the viewer's bundle and the MCAP exporter; the build runs `npm ci` in viewer/ and foxglove/
)
# Extra groups, asked for by the caller: "browser" for the viewer's end-to-end test,
# "fuzz" for scripts/fuzz.sh.
for extra in "$@"; do
  case "$extra" in
    browser) packages+=(chromium) ;;
    fuzz) packages+=(clang libclang-rt-14-dev libomp-dev) ;;  # scripts/fuzz.sh: libFuzzer, OpenMP for clang
    *) echo "install-deps: unknown group '$extra' (known: browser, fuzz)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node and npm may come from outside Debian on a developer's machine: a working
# pair on PATH is as good as the packages.
if command -v node >/dev/null && command -v npm >/dev/null; then
  filtered=()
  for p in "${missing[@]}"; do [[ "$p" == nodejs || "$p" == npm ]] || filtered+=("$p"); done
  missing=("${filtered[@]+"${filtered[@]}"}")
fi
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
else
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then sudo=(sudo -n); fi
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# PyPI's packages (python/requirements.txt, pinned) in .venv/, over Debian's
# Python and its numpy/matplotlib: recreated when the pins change.
venv=.venv
stamp="$venv/.requirements.sha256"
want=$(sha256sum python/requirements.txt | cut -d' ' -f1)
if [ ! -x "$venv/bin/python3" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  echo "install-deps: installing python/requirements.txt into $venv"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  "$venv/bin/pip" install --quiet --disable-pip-version-check -r python/requirements.txt
  echo "$want" > "$stamp"
else
  echo "install-deps: $venv up to date"
fi
