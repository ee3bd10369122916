# SPDX-License-Identifier: Apache-2.0
# Type stubs of the ifsfx extension module (python/*.cpp; docs/python.md), installed beside it.
import os
from typing import Iterator, Literal, Sequence

import numpy as np
import numpy.typing as npt

__version__: str

_Size = tuple[int, int] | str
_View = tuple[float, float, float, float] | str | None
_Colour = str | tuple[int, int, int]
_DType = Literal["uint8", "uint16", "float32"] | npt.DTypeLike
_Image = npt.NDArray[np.uint8] | npt.NDArray[np.uint16] | npt.NDArray[np.float32]
_Path = str | os.PathLike[str]

class Ifs:
    def __init__(
        self,
        maps: npt.ArrayLike,
        probabilities: Sequence[float] | None = None,
        name: str = "",
        allow_expansive: bool = False,
    ) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def maps(self) -> npt.NDArray[np.float64]: ...
    @property
    def probabilities(self) -> list[float]: ...
    @property
    def colours(self) -> list[tuple[float, float, float]]: ...
    @property
    def description(self) -> str: ...
    @property
    def origin(self) -> str: ...
    @property
    def text(self) -> str: ...
    @property
    def contraction(self) -> float: ...
    def to_toml(self) -> str: ...
    def __len__(self) -> int: ...

def load_preset(spec: str, allow_expansive: bool = False) -> Ifs: ...
def presets() -> list[str]: ...
def render(
    preset: str | os.PathLike[str] | Ifs,
    *,
    mode: Literal["attractor", "measure", "tops", "steal"] = "measure",
    size: _Size = (1024, 1024),
    view: _View = None,
    margin: float = 0.05,
    quality: float = 64,
    supersample: int = 1,
    gamma: float = 2.2,
    brightness: float = 4,
    seed: int = 1,
    threads: int = 0,
    exact: bool = True,
    second_symbol: bool = False,
    source: _Image | _Path | None = None,
    colouring: str | None = None,
    background: _Colour = "black",
    alpha: bool = True,
    dtype: _DType = "uint8",
    allow_expansive: bool = False,
    rgb: bool = False,
) -> _Image: ...
def read_image(path: str, *, rgb: bool = False) -> _Image: ...
def write_image(path: str, image: _Image, bits: int = 8, *, rgb: bool = False) -> None: ...

class StealMap:
    @property
    def source_uv(self) -> npt.NDArray[np.float32]: ...
    @property
    def coverage(self) -> npt.NDArray[np.uint8]: ...
    @property
    def size(self) -> tuple[int, int]: ...
    def apply(
        self,
        image: _Image,
        *,
        background: _Colour = "black",
        interpolation: Literal["bilinear", "nearest"] = "bilinear",
        threads: int = 0,
        rgb: bool = False,
    ) -> _Image: ...
    def save(self, path: str) -> None: ...

def steal_map(
    preset: str | os.PathLike[str] | Ifs,
    *,
    size: _Size = (1024, 1024),
    colouring: str | None = None,
    view: _View = None,
    margin: float = 0.05,
    exact: bool = True,
    quality: float = 64,
    seed: int = 1,
    threads: int = 0,
    allow_expansive: bool = False,
) -> StealMap: ...
def load_steal_map(path: str) -> StealMap: ...
def apply(
    map: StealMap,
    image: _Image,
    *,
    background: _Colour = "black",
    interpolation: Literal["bilinear", "nearest"] = "bilinear",
    threads: int = 0,
    rgb: bool = False,
) -> _Image: ...

class TextureFrames(Iterator[_Image]):
    def __iter__(self) -> TextureFrames: ...
    def __next__(self) -> _Image: ...

def texture(
    superpreset: str,
    *,
    size: _Size = (1024, 1024),
    buffers: int = 3,
    steps: int = 0,
    buffer: int = 1,
    mode: Literal["attractor", "tops", "steal", "measure"] = "attractor",
    source: _Image | _Path | None = None,
    seed: int = 1,
    threads: int = 0,
    frame: int = 0,
    crossfade: int = 1,
    dtype: _DType = "uint8",
    rgb: bool = False,
) -> _Image: ...
def textures(
    superpreset: str,
    *,
    size: _Size = (1024, 1024),
    buffers: int = 3,
    steps: int = 0,
    buffer: int = 1,
    mode: Literal["attractor", "tops", "steal", "measure"] = "attractor",
    source: _Image | _Path | None = None,
    seed: int = 1,
    threads: int = 0,
    frames: int | None = None,
    crossfade: int = 1,
    dtype: _DType = "uint8",
    first: int = 0,
    rgb: bool = False,
) -> TextureFrames: ...
