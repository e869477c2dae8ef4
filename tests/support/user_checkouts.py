# SPDX-License-Identifier: BSD-3-Clause
"""The user's checkouts some tests build or compile from, each named by an
environment variable with no default (the libraries are the user's:
docs/testing.md says how a developer gets each). Tests that need one carry
its marker; conftest.py skips them, saying why, when it is not given."""

import os


class UserCheckout:
    """A checkout named by variable, recognised by required_file in it."""

    def __init__(self, variable, marker, name, required_file):
        self.variable = variable
        self.marker = marker
        self.name = name
        self.required_file = required_file
        self.root = os.environ.get(variable, '')

    def found(self):
        return bool(self.root) and os.path.isfile(os.path.join(self.root, self.required_file))

    def missing_reason(self):
        """Why the tests that need the checkout do not run."""
        if not self.root:
            return 'needs an %s checkout: set %s (docs/testing.md)' % (self.name, self.variable)
        return 'no %s checkout at %s=%s (no %s)' % (self.name, self.variable, self.root,
                                                    self.required_file)


MROS_V1 = UserCheckout('MROS_V1_ROOT', 'needs_mros_v1', 'mROS v1', 'mros-lib/Makefile.m')
MROS2 = UserCheckout('MROS2_ROOT', 'needs_mros2', 'mros2', 'src/mros2.cpp')
CHECKOUTS = (MROS_V1, MROS2)
MROS_V1_ROOT = MROS_V1.root
MROS2_ROOT = MROS2.root
