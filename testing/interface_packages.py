# SPDX-License-Identifier: BSD-3-Clause
"""A scratch ROS 2 interface package of messages given as text, in a
workspace's src/, as a benchmark or a test writes one for genmros to read
(what a user writes: a package.xml in the rosidl_interface_packages group
and msg/<Name>.msg files)."""

import os

PACKAGE_XML = '''<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>{description}</description>
  <maintainer email="dev@example.com">colcon-mros developers</maintainer>
  <license>BSD-3-Clause</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>
  <export>
    <build_type>ament_cmake</build_type>
  </export>
</package>
'''


def write_interface_package(workspace, name, messages, description):
    """workspace/src/name with messages ({Name: .msg text}); returns workspace."""
    package = os.path.join(workspace, 'src', name)
    os.makedirs(os.path.join(package, 'msg'), exist_ok=True)
    with open(os.path.join(package, 'package.xml'), 'w') as stream:
        stream.write(PACKAGE_XML.format(name=name, description=description))
    for message, text in messages.items():
        with open(os.path.join(package, 'msg', message + '.msg'), 'w') as stream:
            stream.write(text)
    return workspace
