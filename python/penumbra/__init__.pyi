# Type stubs of the penumbra package (python/penumbra/__init__.py and its extension module).
import os
from typing import Any, Iterable, Mapping, Sequence, SupportsIndex, overload

import numpy as np
import numpy.typing as npt

Vec3 = tuple[float, float, float]
Vec3Like = Sequence[float] | npt.NDArray[np.floating[Any]]
FloatArray = npt.NDArray[np.float32]


class Error(ValueError): ...


class Camera:
    position: Vec3
    target: Vec3
    up: Vec3
    fov: float
    near: float
    def __init__(self) -> None: ...


class Light:
    center: Vec3
    radius: float
    color: Vec3
    intensity: float
    shape: str  # "sphere", "disk" or "rectangle"
    normal: Vec3
    edge_u: Vec3
    edge_v: Vec3
    def __init__(self, center: Vec3Like = ..., radius: float = 0.0, color: Vec3Like = ...,
                 intensity: float = 1.0) -> None: ...


class LightList:
    def __len__(self) -> int: ...
    @overload
    def __getitem__(self, index: SupportsIndex) -> Light: ...
    @overload
    def __getitem__(self, index: slice) -> LightList: ...
    def __setitem__(self, index: SupportsIndex, light: Light) -> None: ...
    def __delitem__(self, index: SupportsIndex) -> None: ...
    def append(self, light: Light) -> None: ...
    def clear(self) -> None: ...
    def pop(self, index: SupportsIndex = ...) -> Light: ...
    def __iter__(self) -> Iterable[Light]: ...


class Scene:
    @property
    def name(self) -> str: ...
    camera: Camera
    lights: LightList
    width: int
    height: int
    @property
    def triangle_count(self) -> int: ...
    @property
    def meshes(self) -> list[dict[str, Any]]: ...
    @property
    def bounds(self) -> tuple[Vec3, Vec3]: ...
    def copy(self) -> Scene: ...


class Frame:
    @property
    def color(self) -> FloatArray: ...  # H x W x 3
    @property
    def visibility(self) -> list[FloatArray]: ...  # H x W per light
    @property
    def depth(self) -> FloatArray: ...  # H x W, reversed-Z
    @property
    def counters(self) -> dict[str, int]: ...
    @property
    def times(self) -> dict[str, float]: ...
    @property
    def prepare_ms(self) -> float: ...
    @property
    def frame_ms(self) -> float: ...
    @property
    def render_ms(self) -> float: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...


SceneSource = str | os.PathLike[str] | Mapping[str, Any]
OptionValue = bool | int | float | str


def load_scene(source: SceneSource, up: str = "y") -> Scene: ...
def builtin_scenes() -> list[str]: ...
def techniques() -> list[dict[str, Any]]: ...
def render(scene: Scene | SceneSource, technique: str = "exact", width: int | None = None,
           height: int | None = None, threads: int = 0, simd: bool = True,
           occlusion_culling: str = "auto", caster_culling: str = "auto", delay_stream: int = 0,
           **options: OptionValue) -> Frame: ...


class Renderer:
    def __init__(self, scene: Scene | SceneSource, technique: str = "exact",
                 width: int | None = None, height: int | None = None, threads: int = 0,
                 simd: bool = True, occlusion_culling: str = "auto", caster_culling: str = "auto",
                 delay_stream: int = 0, **options: OptionValue) -> None: ...
    def render(self) -> Frame: ...
    @property
    def scene(self) -> Scene: ...
    @property
    def prepare_ms(self) -> float: ...
    @property
    def technique(self) -> str: ...


ImageLike = npt.ArrayLike | str | os.PathLike[str]


def compare(a: ImageLike, b: ImageLike, mask: ImageLike | None = None,
            tolerance: float = 0.01) -> dict[str, float]: ...
def read_image(path: str) -> FloatArray: ...
def read_exr(path: str) -> FloatArray: ...
