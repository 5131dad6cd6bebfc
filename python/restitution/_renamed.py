# SPDX-License-Identifier: BSD-3-Clause
"""Result attributes renamed to the JSON keys of the same quantities (docs/cli.md, "Spellings"): the old name
stays until 0.5.0 as a property that warns and returns the new one's value."""

import warnings as _warnings


def add_old_names(cls, renamed):
    """Give cls, for each (old, new) of renamed, a read-only property old that warns and reads new."""
    for old, new in renamed:
        setattr(cls, old, _old_name(cls.__name__, old, new))


def _old_name(owner, old, new):
    def read(self):
        _warnings.warn(f"{owner}.{old} is deprecated and will be removed in 0.5.0; use {new}", DeprecationWarning,
                       stacklevel=2)
        return getattr(self, new)

    return property(read, doc=f"Deprecated until 0.5.0: {new}.")
