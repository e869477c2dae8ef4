# SPDX-License-Identifier: BSD-3-Clause
"""The one exception type genmros reports to users."""

import difflib


class GenmrosError(Exception):
    """A problem in the user's input, reported as one line.

    The line reads ``FILE:LINE: problem`` (or ``FILE: problem`` when no line
    applies) so editors and CI logs can jump to it.
    """

    def __init__(self, problem, path=None, line=None):
        self.problem = problem
        self.path = path
        self.line = line
        super().__init__(str(self))

    def __str__(self):
        if self.path is None:
            return self.problem
        if self.line is None:
            return '%s: %s' % (self.path, self.problem)
        return '%s:%d: %s' % (self.path, self.line, self.problem)


class GenmrosProblems(GenmrosError):
    """Several problems found at once (the fit check's), one line each."""

    def __init__(self, lines):
        self.lines = list(lines)
        super().__init__('\n'.join(self.lines))


def close_match(name, candidates):
    """'; did you mean 'X'?' for the candidate closest to a misspelt name,
    or '' where none is close."""
    matches = difflib.get_close_matches(name, sorted(set(candidates)), n=1, cutoff=0.75)
    return "; did you mean '%s'?" % matches[0] if matches else ''
