"""Keyword arguments = the command line's options. The option classes of the extension
(python/src/options.cpp) have one attribute per option, named and defaulted like the CLI's;
everything here is derived from them, so a new option needs no change in Python."""
import inspect


def keywords(options_class):
    """{keyword: default}, in the order the options are declared."""
    default = options_class()
    return {name: getattr(default, name)
            for name, attribute in vars(options_class).items() if isinstance(attribute, property)}


def build(options_class, given, function):
    """An options_class instance with the given keywords set; TypeError names a wrong keyword or type."""
    known = keywords(options_class)
    options = options_class()
    for name, value in given.items():
        if name not in known:
            raise TypeError(f"{function}() got an unexpected keyword argument {name!r}; "
                            f"options are {', '.join(known)}")
        try:
            setattr(options, name, value)
        except TypeError:
            raise TypeError(f"{function}(): {name}={value!r} has the wrong type "
                            f"(default {known[name]!r})") from None
    return options


def with_options(options_class):
    """Gives the decorated function(..., **options) a signature and docstring listing the options."""
    def decorate(function):
        signature = inspect.signature(function)
        fixed = [p for p in signature.parameters.values() if p.kind is not inspect.Parameter.VAR_KEYWORD]
        extra = [inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=default)
                 for name, default in keywords(options_class).items()]
        function.__signature__ = signature.replace(parameters=fixed + extra)
        listing = ", ".join(f"{name}={default!r}" for name, default in keywords(options_class).items())
        function.__doc__ = (function.__doc__ or "") + f"\n    Options (as on the command line): {listing}.\n"
        return function
    return decorate
