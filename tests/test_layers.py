"""The package's layers: every module imports only its own layer and the
layers below it (cli, targets, integrations, export, generator, and at the
bottom the package root with errors), lazy imports inside functions
included."""

import ast
import os

from conftest import REPO

PACKAGE = os.path.join(REPO, 'colcon_mros')
# Top first; a module's layer is its first name below colcon_mros.
LAYERS = ['cli', 'targets', 'integrations', 'export', 'generator', '']
TOP_MODULES = {'cli': 'cli', '__main__': 'cli', 'errors': '', '__init__': '', '__version__': ''}


def _layer(dotted):
    """The layer of colcon_mros.<dotted>."""
    first = dotted.split('.')[0] if dotted else ''
    return TOP_MODULES.get(first, first)


def _imports(path):
    """The colcon_mros modules (as names below colcon_mros) path imports."""
    with open(path) as stream:
        tree = ast.parse(stream.read(), path)
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names = [node.module + '.' + alias.name if node.module == 'colcon_mros' else
                     node.module for alias in node.names]
        else:
            continue
        for name in names:
            if name == 'colcon_mros' or name.startswith('colcon_mros.'):
                yield name[len('colcon_mros.'):] if '.' in name else ''


def test_every_import_goes_down_the_layers():
    checked = 0
    upward = []
    for directory, _, files in os.walk(PACKAGE):
        for name in sorted(files):
            if not name.endswith('.py'):
                continue
            path = os.path.join(directory, name)
            module = os.path.relpath(path, PACKAGE)[:-3].replace(os.sep, '.')
            own = LAYERS.index(_layer(module))
            for imported in _imports(path):
                checked += 1
                if LAYERS.index(_layer(imported)) < own:
                    upward.append('%s imports colcon_mros.%s' % (module, imported))
    assert checked > 80
    assert upward == []


def test_the_check_sees_an_upward_import(tmp_path):
    module = tmp_path / 'upward.py'
    module.write_text('def f():\n    from colcon_mros.integrations import installed_files\n')
    assert list(_imports(str(module))) == ['integrations']
    assert LAYERS.index(_layer('integrations')) < LAYERS.index(_layer('generator.parse'))
