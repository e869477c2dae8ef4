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

#ifdef MAX_TYPENAME_LENGTH
@[for msg in messages]@
static_assert(sizeof("@(msg.dds_type_name)") <= MAX_TYPENAME_LENGTH,
              "@(msg.dds_type_name) needs MAX_TYPENAME_LENGTH >= @(len(msg.dds_type_name) + 1) (embeddedRTPS' rtps/config.h)");
@[end for]@
#endif
