# SPDX-License-Identifier: BSD-3-Clause
"""Definition-text bytes a header carries, full against compact.

Prints, for the big Debian types and for the whole Debian message set (every
message and service half of the 15 packages the tests use), the bytes of the
definition text in the headers: gencpp's full text and genmros' compact one.
Run by bench/footprint/run.sh, or alone:
    PYTHONPATH=. /usr/bin/python3 bench/footprint/definition_text.py
"""

from colcon_mros.mros_v1.names import RESERVED_NAMES
from colcon_mros.ros1.model import gencpp_definition_text
from colcon_mros.ros1.parse import SpecLoader
from colcon_mros.ros1.workspace import installed_packages, msg_search_path
from testing.ros_paths import ros1_prefixes

DEBIAN_MESSAGE_PACKAGES = [
    'std_msgs', 'geometry_msgs', 'sensor_msgs', 'nav_msgs', 'trajectory_msgs',
    'visualization_msgs', 'diagnostic_msgs', 'actionlib_msgs', 'shape_msgs',
    'stereo_msgs', 'tf2_msgs', 'map_msgs', 'pcl_msgs', 'std_srvs', 'rosgraph_msgs',
]
BIG_TYPES = ['nav_msgs/Odometry', 'sensor_msgs/Image', 'sensor_msgs/JointState',
             'sensor_msgs/PointCloud2', 'visualization_msgs/MarkerArray']


def _type_names(loader, packages):
    names = []
    for package_name in DEBIAN_MESSAGE_PACKAGES:
        package = packages[package_name]
        for path in package.message_files():
            names.append(loader.load_message_file(path, package_name).full_name)
        for path in package.service_files():
            spec = loader.load_service_file(path, package_name)
            names.extend([spec.request.full_name, spec.response.full_name])
    return names


def main():
    packages = installed_packages(ros1_prefixes())
    loader = SpecLoader(msg_search_path(packages), RESERVED_NAMES)
    names = _type_names(loader, packages)

    def size(name, compact):
        return len(gencpp_definition_text(loader.identities.full_text(name, compact)).encode())

    print('Definition text bytes per header (the MD5 sums do not change):')
    print()
    print('| type | full text | compact | compact / full |')
    print('|---|---:|---:|---:|')
    rows = [(name, size(name, False), size(name, True)) for name in BIG_TYPES]
    rows.append(('Debian message set (%d types)' % len(names), sum(size(n, False) for n in names),
                 sum(size(n, True) for n in names)))
    for name, full, compact in rows:
        print('| %s | %d B | %d B | %.2f |' % (name, full, compact, compact / full))


if __name__ == '__main__':
    main()
