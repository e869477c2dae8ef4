"""The package's layers: every module imports only its own layer and the
layers below it, lazy imports inside functions included. The mros2 back
end sits on the ROS 2 front end (ros2), both on the shared core in
generator (output, names, storage, templates), which is also ROS 1's front
end; mros_v1 and mros2 never import each other. The mROS v1
library's subpackage has two: what it is (settings, rules, fit check, its
apps, its aggregates), which the export uses, and what runs it (the fit
flow, its PC target, the fit report), which uses the export."""

import ast
import os

from conftest import REPO

PACKAGE = os.path.join(REPO, 'colcon_mros')
# Top first; a module's layer is the longest of these its name below
# colcon_mros starts with.
LAYERS = ['cli', 'mros_v1.report', 'mros_v1.pc_target', 'mros_v1.patches',
          'mros_v1.firmware_fit', 'integrations', 'export', 'mros_v1', 'mros2', 'ros2', 'generator',
          '']
TOP_MODULES = {'cli': 'cli', '__main__': 'cli', 'errors': '', '__init__': '', '__version__': '',
               'empy_proxy': ''}


def _layer(dotted):
    """The layer of colcon_mros.<dotted>."""
    first = dotted.split('.')[0]
    if first in TOP_MODULES or not dotted:
        return TOP_MODULES.get(first, '')
    return max((layer for layer in LAYERS if layer and (dotted + '.').startswith(layer + '.')),
               key=len)


def _imports(path):
    """The colcon_mros modules (as names below colcon_mros) path imports."""
    with open(path) as stream:
        tree = ast.parse(stream.read(), path)
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names = [node.module + '.' + alias.name for alias in node.names]
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


def test_the_two_mros_lines_do_not_import_each_other():
    crossing = []
    for line, other in (('mros_v1', 'mros2'), ('mros2', 'mros_v1')):
        for directory, _, files in os.walk(os.path.join(PACKAGE, line)):
            for name in sorted(files):
                if name.endswith('.py'):
                    path = os.path.join(directory, name)
                    crossing += [(path, i) for i in _imports(path)
                                 if (i + '.').startswith(other + '.')]
    assert crossing == []


def test_the_check_sees_an_upward_import(tmp_path):
    module = tmp_path / 'upward.py'
    module.write_text('def f():\n    from colcon_mros.integrations import installed_files\n')
    assert list(_imports(str(module))) == ['integrations.installed_files']
    assert LAYERS.index(_layer('integrations')) < LAYERS.index(_layer('generator.parse'))
    # A subpackage's modules in two layers: the PC target above the export,
    # the library's rules below it.
    assert LAYERS.index(_layer('mros_v1.pc_target.build')) < LAYERS.index(_layer('export'))
    assert LAYERS.index(_layer('export.firmware_export')) < LAYERS.index(_layer('mros_v1.rules'))


# The trees beside the package; each shares code with the others only
# through the package.
TREES = ('tests', 'bench', 'scripts', 'evaluation')


def _python_files(tree):
    for directory, _, files in os.walk(os.path.join(REPO, tree)):
        for name in sorted(files):
            if name.endswith('.py'):
                yield os.path.join(directory, name)


def _imported_names(path):
    """The top-level names path imports."""
    with open(path) as stream:
        tree = ast.parse(stream.read(), path)
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name.split('.')[0] for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split('.')[0])
    return names


def test_tests_bench_scripts_and_evaluation_import_nothing_from_each_other():
    modules = {tree: {os.path.basename(path)[:-3] for path in _python_files(tree)}
               | {name for name in os.listdir(os.path.join(REPO, tree))
                  if os.path.isdir(os.path.join(REPO, tree, name))}
               for tree in TREES}
    crossing = []
    checked = 0
    for tree in TREES:
        others = set().union(*(modules[other] for other in TREES if other != tree))
        others -= modules[tree]
        for path in _python_files(tree):
            checked += 1
            crossing += ['%s imports %s' % (os.path.relpath(path, REPO), name)
                         for name in sorted(_imported_names(path) & (others | set(TREES)))]
    assert checked > 50
    assert crossing == []


def test_the_check_sees_a_crossing_import(tmp_path):
    module = tmp_path / 'crossing.py'
    module.write_text('import os\nfrom built_workspace import workspace\n')
    assert _imported_names(str(module)) == {'os', 'built_workspace'}
    assert 'built_workspace' in {os.path.basename(path)[:-3] for path in _python_files('tests')}
