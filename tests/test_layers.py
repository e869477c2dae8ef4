# SPDX-License-Identifier: BSD-3-Clause
"""The package's levels, bottom up: the core; the front ends (ros1 | ros2);
the back ends (mros_v1 | mros2); the export; the integrations; the tools
that work on the user's library; the CLI. Each top-level subpackage of
colcon_mros sits on one level, whole. A module imports its own subpackage
and the levels below it, lazy imports inside functions included; siblings
on a level never import each other, and each back end stands on its own
stack's front end only."""

import ast
import os

from support.checkout import REPO

PACKAGE = os.path.join(REPO, 'colcon_mros')
# Bottom first; a level's subpackages are siblings. '' is the package's
# root modules below everything (errors, __init__); cli.py and __main__
# are the top.
LEVELS = [
    ('',),
    ('core',),
    ('ros1', 'ros2'),
    ('mros_v1', 'mros2'),
    ('export',),
    ('integrations',),
    ('library_tools',),
    ('cli',),
]
ROOT_MODULES = {'__init__': '', '__version__': '', 'errors': '', 'cli': 'cli', '__main__': 'cli'}
# Which stack each front and back end belongs to.
STACKS = {'ros1': 'ROS 1', 'mros_v1': 'ROS 1', 'ros2': 'ROS 2', 'mros2': 'ROS 2'}


def _unit(dotted):
    """The top-level subpackage (or root module's unit) of colcon_mros.<dotted>."""
    first = dotted.split('.')[0] if dotted else ''
    return ROOT_MODULES.get(first, first)


def _level(unit):
    return next(index for index, units in enumerate(LEVELS) if unit in units)


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


def _modules():
    """(dotted name below colcon_mros, path) of every module of the package."""
    for directory, _, files in os.walk(PACKAGE):
        for name in sorted(files):
            if name.endswith('.py'):
                path = os.path.join(directory, name)
                yield os.path.relpath(path, PACKAGE)[:-3].replace(os.sep, '.'), path


def _unit_imports():
    """[(importing unit, imported unit, 'module imports colcon_mros.name')]."""
    found = []
    for module, path in _modules():
        for imported in _imports(path):
            found.append((_unit(module), _unit(imported),
                          '%s imports colcon_mros.%s' % (module, imported)))
    return found


def test_every_subpackage_sits_on_one_level():
    units = {_unit(module) for module, _ in _modules()}
    placed = [unit for units_of_level in LEVELS for unit in units_of_level]
    assert len(placed) == len(set(placed))
    assert units == set(placed)
    assert {name for name in os.listdir(PACKAGE)
            if os.path.isdir(os.path.join(PACKAGE, name)) and name != '__pycache__'} \
        == set(placed) - {'', 'cli'}


def test_every_import_goes_down_the_levels():
    imports = _unit_imports()
    assert len(imports) > 80
    assert [text for unit, imported, text in imports if _level(imported) > _level(unit)] == []


def test_siblings_on_a_level_never_import_each_other():
    assert [text for unit, imported, text in _unit_imports()
            if unit != imported and _level(unit) == _level(imported)] == []


def test_a_back_end_stands_on_its_own_front_end_only():
    assert [text for unit, imported, text in _unit_imports()
            if unit in STACKS and imported in STACKS and STACKS[unit] != STACKS[imported]] == []


def test_no_cycle_between_subpackages():
    graph = {}
    for unit, imported, _ in _unit_imports():
        if unit != imported:
            graph.setdefault(unit, set()).add(imported)
    # Kahn's algorithm: what cannot be ordered lies on a cycle.
    remaining = {unit: set(targets) for unit, targets in graph.items()}
    progress = True
    while remaining and progress:
        progress = False
        for unit in sorted(remaining):
            if not remaining[unit] - {u for u in remaining[unit] if u not in remaining}:
                del remaining[unit]
                progress = True
    assert remaining == {}


def test_the_checks_see_an_upward_and_a_sibling_import(tmp_path):
    module = tmp_path / 'upward.py'
    module.write_text('def f():\n    from colcon_mros.integrations import installed_files\n'
                      'from colcon_mros.ros2.model import ModelBuilder\n')
    assert sorted(_imports(str(module))) == ['integrations.installed_files',
                                             'ros2.model.ModelBuilder']
    assert _level(_unit('integrations.installed_files')) > _level(_unit('ros1.parse'))
    assert _level(_unit('ros2.model')) == _level(_unit('ros1.parse'))
    assert _unit('cli') == _unit('__main__') == 'cli'
    assert _unit('errors') == ''


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


def test_tests_take_their_helpers_from_support_never_from_conftest():
    # conftest.py is pytest's (fixtures, hooks); what modules share is a
    # module of tests/support, imported like any other.
    importing = [os.path.relpath(path, REPO) for path in _python_files('tests')
                 if 'conftest' in _imported_names(path)]
    assert importing == []
