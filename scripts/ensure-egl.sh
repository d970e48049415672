#!/usr/bin/env bash
# Make sure OpenGL through EGL works for the first-person kitchen camera (ewa_mcp/envs/kitchen/camera3d.py):
# the GL vendor-neutral dispatch (libegl1) and Mesa's EGL and drivers (libegl-mesa0, libgl1-mesa-dri), whose
# llvmpipe renders on the CPU where no GPU driver is installed. Installed with apt when running as root.
set -uo pipefail
PACKAGES="libegl1 libgl1-mesa-dri libegl-mesa0"
have() { ldconfig -p 2>/dev/null | grep "libEGL_mesa.so.0" >/dev/null && ldconfig -p 2>/dev/null | grep "libEGL.so.1" >/dev/null; }
if have; then exit 0; fi
if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null; then
  echo "egl: installing $PACKAGES for the kitchen camera"
  export DEBIAN_FRONTEND=noninteractive
  # shellcheck disable=SC2086
  apt-get install -y -qq --no-install-recommends $PACKAGES >/dev/null 2>&1 \
    || { apt-get update -qq >/dev/null 2>&1 && apt-get install -y -qq --no-install-recommends $PACKAGES >/dev/null 2>&1; }
  have && exit 0
fi
cat >&2 <<MSG
egl: OpenGL through EGL was not found; the first-person kitchen camera (observation vision/both) needs it.
Install: sudo apt-get install $PACKAGES   (or choose the top-down map: episode option kitchen_view='map')
MSG
exit 0
