# SPDX-License-Identifier: Apache-2.0
# One set of sampling defaults through every door: the module's keyword defaults are those the
# command line shows in `ifsfx render --help` and `ifsfx filter --help` (all read from the
# library's Sampling and RenderOptions), and both default to the exact descent; fit() and Filter
# default as `ifsfx fit --help` and `ifsfx filter --help` show.
import re

import numpy as np

import ifsfx
from conftest import run_cli

EXPECTED_TESTS = 4


def help_defaults(cli, command):
    """{flag: default} of the `--flag TYPE=DEFAULT` lines of `ifsfx COMMAND --help`."""
    done = run_cli(cli, command, "--help")
    assert done.returncode == 0, done.stderr
    return {m.group(1): float(m.group(2))
            for m in re.finditer(r"^\s+--([a-z-]+) [A-Z]+(?::[^=]*)?=([0-9.]+)", done.stdout, re.M)}


def keyword_defaults(function):
    """{keyword: default} of a binding, from the signature line pybind11 writes."""
    head = function.__doc__.splitlines()[0]
    return {m.group(1): m.group(2) for m in re.finditer(r"(\w+): [^=,]+ = ([^,)]+)", head)}


def test_render_keywords_default_as_the_command_line(cli):
    cli_render = help_defaults(cli, "render")
    py = keyword_defaults(ifsfx.render)
    for key in ("margin", "supersample", "gamma", "brightness", "seed", "threads"):
        assert float(py[key]) == cli_render[key], key
    # size, quality and exact are None unless given (a flame has its own size and quality, and
    # refuses a named exact descent): for an IFS, None is the command's default.
    assert py["size"] == py["quality"] == py["exact"] == "None"
    small = {"size": (24, 24), "seed": 3}
    np.testing.assert_array_equal(ifsfx.render("sierpinski-triangle", **small),
                                  ifsfx.render("sierpinski-triangle", quality=cli_render["quality"],
                                               **small))
    np.testing.assert_array_equal(ifsfx.render("sierpinski-triangle", mode="tops", **small),
                                  ifsfx.render("sierpinski-triangle", mode="tops", exact=True,
                                               **small))
    assert ifsfx.render("sierpinski-triangle", quality=1).shape == (1024, 1024, 3)
    steal = keyword_defaults(ifsfx.steal_map)
    for key in ("margin", "quality", "seed", "threads"):
        assert float(steal[key]) == cli_render[key], key
    assert steal["exact"] == "True"


def test_filter_samples_with_the_same_defaults_as_render(cli):
    cli_render = help_defaults(cli, "render")
    cli_filter = help_defaults(cli, "filter")
    for key in ("margin", "quality", "seed", "threads"):
        assert cli_filter[key] == cli_render[key], key



def all_help_defaults(cli, command):
    """{flag: default text} of every `[-x,]--flag TYPE...=DEFAULT` line of the help."""
    done = run_cli(cli, command, "--help")
    assert done.returncode == 0, done.stderr
    return {m.group(1): m.group(2)
            for m in re.finditer(r"^\s+(?:-\w,)?--([a-z-]+) [^=\n]*?=(\S+)", done.stdout, re.M)}


def same(py, cli_text):
    """A keyword default (its repr in the signature) equals the help's default text."""
    value = py.strip("'")
    try:
        return float(value) == float(cli_text)
    except ValueError:
        return value == cli_text


def test_fit_keywords_default_as_the_fit_command(cli):
    cli_fit = all_help_defaults(cli, "fit")
    py = keyword_defaults(ifsfx.fit)
    names = {"maps": "n", "seed": "seed", "init": "init", "size": "size",
             "max-seconds": "max_seconds", "max-evaluations": "max_evaluations",
             "reseed-share": "reseed_share", "grow-share": "grow_share", "threads": "threads"}
    for flag, key in names.items():
        assert same(py[key], cli_fit[flag]), (flag, py[key], cli_fit[flag])
    assert "threshold" not in cli_fit and py["threshold"] == "None"  # Otsu
    assert py["invert"] == "False"


def test_filter_keywords_default_as_the_filter_command(cli):
    cli_filter = all_help_defaults(cli, "filter")
    py = keyword_defaults(ifsfx.Filter.__init__)
    flags = ["preset", "margin", "quality", "mix", "background", "seed", "threads",
             "interpolation", "animate", "drift-amount", "drift-speed", "keyframe-interval",
             "superifs", "buffers", "loop", "fps"]
    for flag in flags:
        key = flag.replace("-", "_")
        assert same(py[key], cli_filter[flag]), (flag, py[key], cli_filter[flag])
    assert py["exact"] == "None" and py["view"] == "None" and py["colouring"] == "None"
    assert py["size"] == "None"  # the frame's, as --size
