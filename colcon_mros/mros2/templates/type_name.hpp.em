@# SPDX-License-Identifier: BSD-3-Clause
namespace message_traits
{
@[for msg in messages]@
template <>
struct TypeName<@(msg.cpp_name)*>
{
  static const char* value() { return "@(msg.dds_type_name)"; }
};
@[end for]@
}  // namespace message_traits

