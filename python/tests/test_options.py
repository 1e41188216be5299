"""Every option of `acd decompose` and `acd evaluate` is a keyword argument with the same name and default."""
import inspect
import re

import pytest

import acd
from conftest import l_shape, run_cli, without_timing

# Options of the command with no keyword, and why: where files go and what is printed (the
# functions return arrays and a dict and print nothing).
CLI_ONLY = {"help", "out", "quiet", "json"}
# Options whose work needs a folder, done by another function: (function, the argument for the value).
# The simulator files of --format: acd.write_simulator_files(folder, decomposition, model, formats).
OTHER_FUNCTION = {"format": (acd.write_simulator_files, "formats")}
# Keyword arguments that are not options: the progress callback, the faces of a model given as arrays.
NOT_OPTIONS = {"progress", "model_faces"}


def same_default(keyword_default, cli_default):
    if str(keyword_default).lower() == cli_default.lower():
        return True
    try:
        return float(keyword_default) == float(cli_default)
    except (TypeError, ValueError):
        return False


def cli_options(cli, *subcommand):
    """{long option: default or None} from `acd SUBCOMMAND --help`."""
    _, out, _ = run_cli(cli, *subcommand, "--help")
    options = {}
    for line in out.splitlines():
        m = re.match(r"\s+(?:-\w,)?--([\w-]+)(?:\s+\S+?(?:=(\S+))?)?(?:\s|$)", line)
        if m:
            options[m.group(1)] = m.group(2)
    return options


def check(cli, subcommand, function):
    keywords = {name: p.default for name, p in inspect.signature(function).parameters.items()
                if p.kind is inspect.Parameter.KEYWORD_ONLY and name not in NOT_OPTIONS}
    options = cli_options(cli, subcommand)
    assert options, "could not read the options from --help"
    for option, default in options.items():
        if option in CLI_ONLY:
            continue
        if option in OTHER_FUNCTION:
            other, argument = OTHER_FUNCTION[option]
            assert argument in inspect.signature(other).parameters, f"--{option}: {other.__name__}({argument}=)"
            continue
        keyword = option.replace("-", "_")
        assert keyword in keywords, (
            f"`acd {subcommand} --{option}` has no keyword argument in acd.{function.__name__}: add one line "
            f"for it in python/src/options.cpp (or list it in CLI_ONLY in {__file__} with the reason)")
        if default is not None:
            assert same_default(keywords[keyword], default), \
                f"--{option} defaults to {default} but {keyword} to {keywords[keyword]}"
    for keyword in keywords:
        assert keyword.replace("_", "-") in options, f"{keyword} is not an option of `acd {subcommand}`"


def test_decompose_keywords_are_the_cli_options(cli):
    check(cli, "decompose", acd.decompose)


def test_evaluate_keywords_are_the_cli_options(cli):
    check(cli, "evaluate", acd.evaluate)


@pytest.mark.parametrize("mode", [acd.decompose_surface, acd.decompose_exact])
def test_mode_keywords_are_cli_options_with_their_defaults(cli, mode):
    """The functions decompose(surface=True) and decompose(exact=True) route to."""
    options = cli_options(cli, "decompose")
    for name, p in inspect.signature(mode).parameters.items():
        if p.kind is inspect.Parameter.KEYWORD_ONLY and name not in NOT_OPTIONS:
            option = name.replace("_", "-")
            assert option in options, f"{mode.__name__}({name}=) is not an option of `acd decompose`"
            if options[option] is not None:
                assert same_default(p.default, options[option]), f"{mode.__name__}({name}=)"


def test_modes_route_to_their_functions():
    """decompose(surface=True) is decompose_surface, decompose(exact=True) decompose_exact, with the
    keywords that mode takes (the others are ignored, as on the command line)."""
    mesh = l_shape()
    routed = acd.decompose(mesh, surface=True, tau=0.2, no_merge=True, density=5.0)
    direct = acd.decompose_surface(mesh, tau=0.2, no_merge=True)
    assert isinstance(routed, acd.SurfaceDecomposition)
    assert without_timing(routed.report) == without_timing(direct.report)
    routed = acd.decompose(mesh, exact=True, tau=0.2, exact_time_limit=30)
    direct = acd.decompose_exact(mesh, exact_time_limit=30)
    assert without_timing(routed.report) == without_timing(direct.report)
    assert routed.report["parameters"]["time_limit_seconds"] == 30
