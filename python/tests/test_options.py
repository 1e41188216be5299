"""Every option of `acd decompose` and `acd evaluate` is a keyword argument with the same name and default."""
import inspect
import re

import acd
from conftest import run_cli

# Options of the command with no keyword, and why: where files go and what is printed (the
# functions return arrays and a dict and print nothing), and modes served by another function.
CLI_ONLY = {"help", "out", "quiet", "surface", "exact", "exact-time-limit", "exact-memory", "exact-tolerance", "json"}
# Simulator files: written by acd.write_simulator_files(folder, decomposition, model, formats).
CLI_ONLY |= {"format"}
# Scene files mesh by mesh into folders: the functions read a scene's meshes merged, as the default.
CLI_ONLY |= {"per-mesh"}
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


def test_surface_keywords_are_a_subset_of_the_cli_options(cli):
    options = cli_options(cli, "decompose")
    for name, p in inspect.signature(acd.decompose_surface).parameters.items():
        if p.kind is inspect.Parameter.KEYWORD_ONLY and name not in NOT_OPTIONS:
            assert name.replace("_", "-") in options
