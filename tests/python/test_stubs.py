# SPDX-License-Identifier: Apache-2.0
# The type stubs (python/ifsfx.pyi, installed beside the module) describe the module as built:
# the same public names, and for every function the same keywords with the same defaults as the
# signatures pybind11 shows in help().
import ast
import os

import ifsfx

EXPECTED_TESTS = 4

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
    assert checked == 12  # presets, load_preset, render, render_flame, ..., textures, fit


def check_function(node, built):
    a = node.args
    names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
    defaults = [ast.literal_eval(d)
                for d in a.defaults + [d for d in a.kw_defaults if d is not None]]
    built_names, built_defaults = signature_of(built.__doc__)
    if names[:1] == ["self"]:
        names = names[1:]
        built_names = built_names[1:]
    assert names == built_names, node.name
    assert defaults == built_defaults, node.name


def test_the_fractaldb_submodule_has_the_stub_names_keywords_and_defaults():
    # ifsfx.fractaldb is stubbed as a class of static functions (one stub file, one module).
    stub = next(n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == "fractaldb")
    stubbed = {n.name for n in stub.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {name for name in dir(ifsfx.fractaldb) if not name.startswith("_")}
    assert stubbed == public
    checked = 0
    for node in stub.body:
        if isinstance(node, ast.FunctionDef):
            check_function(node, getattr(ifsfx.fractaldb, node.name))
            checked += 1
        elif isinstance(node, ast.ClassDef):
            cls = getattr(ifsfx.fractaldb, node.name)
            members = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
            built = {name for name in dir(cls) if not name.startswith("_")}
            assert members - {"__init__", "__len__", "__getitem__", "__iter__", "__next__"} == built, node.name
            init = next((n for n in node.body if isinstance(n, ast.FunctionDef) and n.name == "__init__"), None)
            if init is not None:
                check_function(init, cls.__init__)
                checked += 1
    assert checked == 7  # 5 functions, Category() and Dataset()


def test_the_filter_class_has_the_stub_members_keywords_and_defaults():
    stub = next(n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == "Filter")
    methods = {n.name: n for n in stub.body if isinstance(n, ast.FunctionDef)}
    built = {name for name in dir(ifsfx.Filter) if not name.startswith("_")}
    assert set(methods) - {"__init__", "__call__"} == built
    for name in ("__init__", "__call__", "apply"):
        check_function(methods[name], getattr(ifsfx.Filter, name))
