# SPDX-License-Identifier: Apache-2.0
# The type stubs (python/ifsfx.pyi, installed beside the module) describe the module as built:
# the same public names, and for every function the same keywords with the same defaults as the
# signatures pybind11 shows in help().
import ast
import os

import ifsfx

EXPECTED_TESTS = 2

STUBS = os.path.join(os.path.dirname(ifsfx.__file__), "ifsfx.pyi")


def stub_tree():
    with open(STUBS, encoding="utf-8") as f:
        return ast.parse(f.read())


def test_the_stubs_name_every_public_name_of_the_module():
    tree = stub_tree()
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    stubbed |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    public = {name for name in dir(ifsfx) if not name.startswith("_")} | {"__version__"}
    assert stubbed - {"__version__"} == public - {"__version__"}


def signature_of(doc):
    """The keywords and defaults of pybind11's first docstring line, `name(a: T = d, ...) -> R`."""
    head = doc.splitlines()[0]
    args = head[head.index("(") + 1:head.rindex(") ->")]
    tree = ast.parse(f"def f({args}): pass".replace("numpy.ndarray", "object"))
    a = tree.body[0].args
    names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
    defaults = a.defaults + [d for d in a.kw_defaults if d is not None]
    return names, [ast.literal_eval(d) for d in defaults]


def test_each_function_has_the_stub_keywords_and_defaults():
    checked = 0
    for node in stub_tree().body:
        if not isinstance(node, ast.FunctionDef):
            continue
        a = node.args
        names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
        defaults = [ast.literal_eval(d)
                    for d in a.defaults + [d for d in a.kw_defaults if d is not None]]
        built_names, built_defaults = signature_of(getattr(ifsfx, node.name).__doc__)
        assert names == built_names, node.name
        assert defaults == built_defaults, node.name
        checked += 1
    assert checked == 10  # presets, load_preset, render, ..., textures
