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

class Flame:
    @property
    def name(self) -> str: ...
    @property
    def size(self) -> tuple[int, int]: ...
    @property
    def text(self) -> str: ...
    def __len__(self) -> int: ...

def load_preset(spec: str, allow_expansive: bool = False) -> Ifs | Flame: ...
def presets() -> list[str]: ...
def render(
    preset: str | os.PathLike[str] | Ifs | Flame,
    *,
    mode: Literal["attractor", "measure", "tops", "steal"] = "measure",
    size: _Size | None = None,
    view: _View = None,
    margin: float = 0.05,
    quality: float | None = None,
    supersample: int = 1,
    gamma: float = 2.2,
    brightness: float = 4,
    seed: int = 1,
    threads: int = 0,
    exact: bool | None = None,
    second_symbol: bool = False,
    source: _Image | _Path | None = None,
    colouring: str | None = None,
    background: _Colour | None = None,
    alpha: bool = True,
    dtype: _DType = "uint8",
    allow_expansive: bool = False,
    rgb: bool = False,
) -> _Image: ...
def render_flame(
    spec: str,
    *,
    size: _Size | None = None,
    quality: float | None = None,
    seed: int = 1,
    threads: int = 0,
    alpha: bool = False,
    background: str | None = None,
    dtype: _DType = "uint8",
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

def fit(
    target: _Path | npt.ArrayLike,
    n: int = 4,
    *,
    seed: int = 1,
    init: Literal["search", "moments"] = "search",
    threshold: float | None = None,
    invert: bool = False,
    size: int | str = 128,
    max_seconds: float = 30.0,
    max_evaluations: int = 250000,
    reseed_share: float = 0.15,
    grow_share: float = 0.0,
    threads: int = 0,
    name: str | None = None,
    rgb: bool = False,
) -> Ifs: ...

class Filter:
    def __init__(
        self,
        preset: _Path = "barnsley-fern",
        *,
        colouring: _Path | None = None,
        view: _View = None,
        margin: float = 0.05,
        quality: float = 64.0,
        mix: float = 0.0,
        background: _Colour = "black",
        exact: bool | None = None,
        seed: int = 1,
        threads: int = 0,
        interpolation: Literal["bilinear", "nearest"] = "bilinear",
        animate: Literal["none", "drift", "superifs"] | None = "none",
        drift_amount: float = 0.05,
        drift_speed: float = 0.2,
        keyframe_interval: int = 12,
        superifs: _Path = "paper-fig4",
        buffers: int = 3,
        loop: int = 0,
        size: _Size | None = None,
        frame_size: _Size | None = None,
        fps: float = 25.0,
        rgb: bool = False,
    ) -> None: ...
    def __call__(
        self, frame: npt.NDArray[np.uint8], index: int | None = None
    ) -> npt.NDArray[np.uint8]: ...
    def apply(
        self, frame: npt.NDArray[np.uint8], index: int | None = None
    ) -> npt.NDArray[np.uint8]: ...
    @property
    def index(self) -> int: ...
    @index.setter
    def index(self, index: int) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def frame_size(self) -> tuple[int, int] | None: ...
    @property
    def size(self) -> tuple[int, int] | None: ...
    @property
    def stalls(self) -> int: ...

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

# ifsfx.fractaldb, a submodule (also `import ifsfx.fractaldb`): written here as a class of static
# functions, as one stub file cannot hold a second module.
_Category = str | os.PathLike[str] | fractaldb.Category
_Draw = Literal["point_gray", "point_color", "patch_gray", "patch_color"]

class fractaldb:
    class Category:
        def __init__(
            self,
            maps: npt.ArrayLike,
            probabilities: Sequence[float] | None = None,
            name: str = "",
        ) -> None: ...
        @property
        def name(self) -> str: ...
        @property
        def maps(self) -> npt.NDArray[np.float64]: ...
        @property
        def probabilities(self) -> list[float]: ...
        @property
        def text(self) -> str: ...
        @property
        def contraction_rate(self) -> float: ...
        def __len__(self) -> int: ...

    class Images(Iterator[tuple[npt.NDArray[np.uint8], int]]):
        def __iter__(self) -> fractaldb.Images: ...
        def __next__(self) -> tuple[npt.NDArray[np.uint8], int]: ...
        def __len__(self) -> int: ...

    class Dataset:
        def __init__(
            self,
            categories: _Category | Sequence[_Category],
            weights: float | str | os.PathLike[str] | npt.ArrayLike = 0.1,
            *,
            draw: _Draw = "patch_gray",
            size: _Size = (512, 512),
            padding: int | tuple[int, int] | str = (6, 6),
            iterations: int = 100000,
            instances: int = 10,
            seed: int = 1,
            rgb: bool = False,
        ) -> None: ...
        def __len__(self) -> int: ...
        def __getitem__(self, index: int) -> tuple[npt.NDArray[np.uint8], int]: ...
        def __iter__(self) -> fractaldb.Images: ...
        def shard(self, index: int, count: int) -> fractaldb.Images: ...
        def path(self, index: int) -> str: ...
        def key(self, index: int) -> tuple[int, int, int, int]: ...
        @property
        def classes(self) -> list[str]: ...
        @property
        def categories(self) -> list[fractaldb.Category]: ...
        @property
        def weights(self) -> npt.NDArray[np.float64]: ...
        @property
        def draw(self) -> str: ...
        @property
        def size(self) -> tuple[int, int]: ...
        @property
        def padding(self) -> tuple[int, int]: ...
        @property
        def iterations(self) -> int: ...
        @property
        def instances(self) -> int: ...
        @property
        def seed(self) -> int: ...
        @property
        def rgb(self) -> bool: ...

    @staticmethod
    def read_category(path: str | os.PathLike[str]) -> fractaldb.Category: ...
    @staticmethod
    def read_categories(
        paths: _Category | Sequence[_Category],
    ) -> list[fractaldb.Category]: ...
    @staticmethod
    def read_weights(path: str | os.PathLike[str]) -> npt.NDArray[np.float64]: ...
    @staticmethod
    def weights_table(step: float = 0.1) -> npt.NDArray[np.float64]: ...
    @staticmethod
    def search(
        categories: int = 1000,
        *,
        rate: float = 0.2,
        points: int = 100000,
        seed: int = 1,
    ) -> list[fractaldb.Category]: ...
