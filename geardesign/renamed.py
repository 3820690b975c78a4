"""Keywords renamed for one name per quantity (docs/glossary.md): the old name keeps working for one release,
with a :class:`DeprecationWarning` that names the new one."""
from __future__ import annotations

import functools
import warnings

from .errors import GearDesignError

__all__ = ["renamed_keywords"]


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
