"""The first-person kitchen camera: AI2-THOR's view (90° field of view, eye 1.575 m up, 300×300 by default)
rendered with OpenGL through moderngl on a headless EGL context.

EGL picks the device: a GPU where its driver is installed, otherwise Mesa's CPU renderer (llvmpipe). No display
and no window are needed. One context serves the whole process (created on first use, again after a fork) and
renders one frame at a time under a lock. What is drawn comes from scene3d.py (parts from metadata); the meshes
from meshes.py are uploaded once and every part is one instance of one of them, so a frame is a handful of draw
calls. The same metadata gives the same bytes on a machine: the scene is built in a fixed order, nothing is
random or timed, and the rasteriser is deterministic.
"""

from __future__ import annotations

import math
import os
import threading
from array import array
from collections.abc import Sequence
from typing import Any

from PIL import Image

from .kitchen_map import png_bytes
from .meshes import FLOATS_PER_VERTEX, MESHES
from .scene3d import CameraPose, Part, SceneBuilder, camera_pose

FIELD_OF_VIEW = 90.0  # degrees, vertical, as AI2-THOR's default camera
DEFAULT_SIZE = 300
MAX_SIZE = 2048
NEAR, FAR = 0.02, 30.0
SAMPLES = 4  # multisampling: thin things (knives, knobs) stay visible at 300×300

EGL_PACKAGES = "libegl1 libgl1-mesa-dri libegl-mesa0"
INSTALL_HINT = (f"the first-person kitchen camera needs OpenGL through EGL: install the Debian/Ubuntu packages "
                f"{EGL_PACKAGES} (`apt-get install {EGL_PACKAGES}`, which `make install` does as root; "
                f"scripts/ensure-egl.sh) and the Python package moderngl (in requirements.lock), or choose the "
                f"top-down map with the episode option kitchen_view='map'")

_VERTEX_SHADER = """
#version 330
in vec3 in_position;
in vec3 in_normal;
in vec3 in_c0;
in vec3 in_c1;
in vec3 in_c2;
in vec3 in_t;
in vec4 in_colour;
uniform mat4 view_proj;
uniform float held;
out vec3 v_world;
out vec3 v_normal;
out vec4 v_colour;
void main() {
    mat3 m = mat3(in_c0, in_c1, in_c2);
    vec3 world = m * in_position + in_t;
    v_world = world;
    v_normal = transpose(inverse(m)) * in_normal;
    v_colour = in_colour;
    vec4 clip = view_proj * vec4(world, 1.0);
    // The held object is drawn over everything: its depths are squeezed into the nearest sliver.
    clip.z = mix(clip.z, clip.z * 0.01 - 0.99 * clip.w, held);
    gl_Position = clip;
}
"""

_FRAGMENT_SHADER = """
#version 330
in vec3 v_world;
in vec3 v_normal;
in vec4 v_colour;
uniform vec3 eye;
out vec4 f_colour;
void main() {
    vec3 n = normalize(v_normal);
    vec3 to_eye = normalize(eye - v_world);
    if (dot(n, to_eye) < 0.0) n = -n;  // two-sided: open boxes are seen from inside
    vec3 sun = normalize(vec3(0.35, 1.0, 0.25));
    float diffuse = max(dot(n, sun), 0.0);
    float head = max(dot(n, to_eye), 0.0);
    vec3 lit = v_colour.rgb * (0.34 + 0.40 * diffuse + 0.30 * head);
    float glow = v_colour.a;
    f_colour = vec4(min(mix(lit, v_colour.rgb * 1.15, glow), vec3(1.0)), 1.0);
}
"""


class CameraUnavailable(RuntimeError):
    """No OpenGL context could be made; the message names the packages to install."""


def _matmul(a: list[list[float]], b: list[list[float]]) -> list[list[float]]:
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def view_projection(pose: CameraPose, width: int, height: int) -> list[float]:
    """Column-major 4×4 for GL. Image rows come out top first (the projection flips y)."""
    right, up, forward = pose.basis()
    e = pose.eye

    def dot(v: tuple[float, float, float]) -> float:
        return v[0] * e[0] + v[1] * e[1] + v[2] * e[2]

    view = [[right[0], right[1], right[2], -dot(right)],
            [up[0], up[1], up[2], -dot(up)],
            [-forward[0], -forward[1], -forward[2], dot(forward)],
            [0.0, 0.0, 0.0, 1.0]]
    t = math.tan(math.radians(FIELD_OF_VIEW) / 2)
    aspect = width / height
    proj = [[1 / (aspect * t), 0.0, 0.0, 0.0],
            [0.0, -1 / t, 0.0, 0.0],
            [0.0, 0.0, (FAR + NEAR) / (NEAR - FAR), 2 * FAR * NEAR / (NEAR - FAR)],
            [0.0, 0.0, -1.0, 0.0]]
    m = _matmul(proj, view)
    return [m[r][c] for c in range(4) for r in range(4)]


def pack(parts: Sequence[Part]) -> dict[str, array]:
    """Per mesh, the instance data: the 3×3 (columns), the translation, the colour and the glow."""
    out: dict[str, array] = {name: array("f") for name in MESHES}
    for p in parts:
        a, t = math.radians(p.yaw), math.radians(p.tilt)
        ca, sa, ct, st = math.cos(a), math.sin(a), math.cos(t), math.sin(t)
        sx, sy, sz = (max(v, 1e-4) for v in p.size)
        # R = Ry(yaw, AI2-THOR's sense) · Rz(tilt); columns of R·S
        c0 = (ca * ct * sx, st * sx, -sa * ct * sx)
        c1 = (-ca * st * sy, ct * sy, sa * st * sy)
        c2 = (sa * sz, 0.0, ca * sz)
        out[p.mesh].extend((*c0, *c1, *c2, *p.center, *p.colour, p.glow))
    return out


class _Renderer:
    def __init__(self) -> None:
        try:
            import moderngl
        except ImportError as exc:
            raise CameraUnavailable(f"moderngl is not installed ({exc}); {INSTALL_HINT}") from None
        try:
            create: Any = moderngl.create_context  # its stubs type the backend keyword wrongly
            self.ctx = create(standalone=True, backend="egl", require=330)
        except Exception as exc:  # glcontext raises plain Exceptions whose text names the EGL call that failed
            raise CameraUnavailable(f"no EGL OpenGL context could be created ({exc}); {INSTALL_HINT}") from None
        self.moderngl = moderngl
        self.pid = os.getpid()
        self.renderer = str(self.ctx.info.get("GL_RENDERER", "unknown"))
        self.program: Any = self.ctx.program(vertex_shader=_VERTEX_SHADER, fragment_shader=_FRAGMENT_SHADER)
        self.meshes = {name: self.ctx.buffer(make().tobytes()) for name, make in MESHES.items()}
        self.counts = {name: len(make()) // FLOATS_PER_VERTEX for name, make in MESHES.items()}
        self.instances: dict[tuple[str, bool], tuple[Any, Any, int]] = {}
        self.targets: dict[tuple[int, int], tuple[Any, Any]] = {}
        self.scene = SceneBuilder()

    def _vao(self, mesh: str, held: bool, nbytes: int) -> Any:
        current = self.instances.get((mesh, held))
        if current is None or current[2] < nbytes:
            if current is not None:
                current[0].release()
                current[1].release()
            size = max(4096, 1 << (nbytes - 1).bit_length())
            buffer = self.ctx.buffer(reserve=size, dynamic=True)
            vao = self.ctx.vertex_array(self.program, [
                (self.meshes[mesh], "3f 3f", "in_position", "in_normal"),
                (buffer, "3f 3f 3f 3f 4f/i", "in_c0", "in_c1", "in_c2", "in_t", "in_colour"),
            ])
            current = self.instances[(mesh, held)] = (buffer, vao, size)
        return current

    def _target(self, width: int, height: int) -> tuple[Any, Any]:
        target = self.targets.get((width, height))
        if target is None:
            ms = self.ctx.framebuffer(
                color_attachments=[self.ctx.renderbuffer((width, height), 4, samples=SAMPLES)],
                depth_attachment=self.ctx.depth_renderbuffer((width, height), samples=SAMPLES))
            plain = self.ctx.framebuffer(color_attachments=[self.ctx.renderbuffer((width, height), 4)])
            target = self.targets[(width, height)] = (ms, plain)
        return target

    def render(self, metadata: dict[str, Any], reachable: Sequence[tuple[float, float]], width: int,
               height: int) -> Image.Image:
        world, held = self.scene.build(metadata, reachable)
        pose = camera_pose(metadata)
        ms, plain = self._target(width, height)
        ms.use()
        ms.clear(0.0, 0.0, 0.0, 1.0, depth=1.0)
        self.ctx.enable_only(self.moderngl.DEPTH_TEST)
        self.program["view_proj"].write(array("f", view_projection(pose, width, height)).tobytes())
        self.program["eye"].value = pose.eye
        for is_held, parts in ((False, world), (True, held)):
            self.program["held"].value = 1.0 if is_held else 0.0
            for mesh, data in pack(parts).items():
                if not data:
                    continue
                raw = data.tobytes()
                buffer, vao, _ = self._vao(mesh, is_held, len(raw))
                buffer.orphan()
                buffer.write(raw)
                vao.render(self.moderngl.TRIANGLES, vertices=self.counts[mesh], instances=len(data) // 16)
        self.ctx.copy_framebuffer(plain, ms)
        raw = plain.read(components=3, alignment=1)
        return Image.frombytes("RGB", (width, height), raw)


_lock = threading.Lock()
_renderer: _Renderer | None = None


def _get() -> _Renderer:
    global _renderer
    if _renderer is None or _renderer.pid != os.getpid():  # a forked child cannot use its parent's context
        _renderer = _Renderer()
    return _renderer


def check_size(width: int, height: int) -> None:
    for name, value in (("width", width), ("height", height)):
        if not isinstance(value, int) or not 16 <= value <= MAX_SIZE:
            raise ValueError(f"the kitchen camera's {name} must be a whole number of pixels from 16 to {MAX_SIZE}, "
                             f"not {value!r}")


def render_frame(metadata: dict[str, Any], reachable: Sequence[tuple[float, float]], *,
                 width: int = DEFAULT_SIZE, height: int = DEFAULT_SIZE) -> Image.Image:
    """The agent's view of the kitchen described by AI2-THOR ``metadata``. Raises CameraUnavailable."""
    check_size(width, height)
    with _lock:
        return _get().render(metadata, reachable, width, height)


def render_png(metadata: dict[str, Any], reachable: Sequence[tuple[float, float]], *,
               width: int = DEFAULT_SIZE, height: int = DEFAULT_SIZE) -> bytes:
    return png_bytes(render_frame(metadata, reachable, width=width, height=height))


def renderer_name() -> str:
    """The OpenGL renderer EGL chose (e.g. 'llvmpipe (LLVM 15.0.6, 256 bits)' on the CPU)."""
    with _lock:
        return _get().renderer
