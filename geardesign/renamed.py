"""Keywords renamed for one name per quantity (docs/glossary.md), or grouped into one options object: the old way
keeps working for one release, with a :class:`DeprecationWarning` that names the new one."""
from __future__ import annotations

import functools
import warnings

from .errors import GearDesignError

__all__ = ["renamed_keywords", "grouped_keywords"]


def renamed_keywords(**old_to_new):
    """Decorator: a call with an old keyword (``speed_rpm=``) runs as if the new one (``n_rpm=``) were given,
    after a DeprecationWarning; both at once are refused by name. The signature shows only the new names.

    >>> import warnings
    >>> @renamed_keywords(speed_rpm="n_rpm")
    ... def f(n_rpm):
    ...     return n_rpm
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     f(speed_rpm=1500), str(w[0].message)
    (1500, 'f(speed_rpm=...) is deprecated: use n_rpm= (one name per quantity, docs/glossary.md)')
    """
    def wrap(func):
        @functools.wraps(func)
        def call(*args, **kwargs):
            for old, new in old_to_new.items():
                if old in kwargs:
                    if new in kwargs:
                        raise GearDesignError(f"{func.__name__}: give {new}, not both {new} and its old name {old}")
                    warnings.warn(f"{func.__name__}({old}=...) is deprecated: use {new}= (one name per quantity, "
                                  f"docs/glossary.md)", DeprecationWarning, stacklevel=2)
                    kwargs[new] = kwargs.pop(old)
            return func(*args, **kwargs)
        call.renamed_keywords = dict(old_to_new)
        return call
    return wrap


def grouped_keywords(into: str, group, names):
    """Decorator: keywords among ``names`` given one by one run as if grouped into ``into=group(**those)`` (an
    options object, ``group`` its class), after a DeprecationWarning that names the object; with ``into=`` given
    as well they are refused by name. The signature shows only ``into``.

    >>> import warnings
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Opts:
    ...     nu40: float = 220.0
    >>> @grouped_keywords("options", Opts, ("nu40",))
    ... def f(options=None):
    ...     return options
    >>> with warnings.catch_warnings(record=True) as w:
    ...     warnings.simplefilter("always")
    ...     f(nu40=320), str(w[0].message)
    (Opts(nu40=320), 'f(nu40=...) is deprecated: use options=Opts(nu40=...) (one way to give them, docs/glossary.md)')
    """
    names = tuple(names)

    def wrap(func):
        @functools.wraps(func)
        def call(*args, **kwargs):
            loose = [k for k in names if k in kwargs]
            if loose:
                if kwargs.get(into) is not None:
                    raise GearDesignError(f"{func.__name__}: give the options either as {into}= or as keywords, not "
                                          f"both: {', '.join(loose)}")
                given = ", ".join(f"{k}=..." for k in loose)
                warnings.warn(f"{func.__name__}({given}) is deprecated: use {into}={group.__name__}({given}) (one way "
                              f"to give them, docs/glossary.md)", DeprecationWarning, stacklevel=2)
                kwargs[into] = group(**{k: kwargs.pop(k) for k in loose})
            return func(*args, **kwargs)
        call.grouped_keywords = (into, names)
        return call
    return wrap
