"""The user's mROS v1 checkout the tests build the real library from:
MROS_V1_ROOT, with no default (the library is the user's; docs/testing.md
says how a developer gets one). Tests that need it carry the needs_mros_v1
marker; conftest.py skips them, saying why, when it is not given."""

import os

MROS_V1_ROOT = os.environ.get('MROS_V1_ROOT', '')


def checkout_found(root=MROS_V1_ROOT):
    return bool(root) and os.path.isfile(os.path.join(root, 'mros-lib', 'Makefile.m'))


def missing_reason(root=MROS_V1_ROOT):
    """Why the tests that need a checkout do not run."""
    if not root:
        return 'needs an mROS v1 checkout: set MROS_V1_ROOT (docs/testing.md)'
    return 'no mROS v1 checkout at MROS_V1_ROOT=%s (no mros-lib/Makefile.m)' % root
