"""Python protobuf classes of areagraph's messages, built from the descriptors compiled into the
C++ module: no generated code, and the same message definitions as the tools that wrote them."""

from . import _core

_classes = {}


def parse(type_name, payload):
    """The message `type_name` (e.g. "areagraph.proto.AreaGraph") parsed from `payload`."""
    if not _classes:
        _build_classes()
    return _classes[type_name].FromString(payload)


def _build_classes():
    from google.protobuf import descriptor_pb2, descriptor_pool, message_factory

    files = descriptor_pb2.FileDescriptorSet.FromString(_core.descriptor_set()).file
    pool = descriptor_pool.DescriptorPool()
    for file in files:
        pool.AddSerializedFile(file.SerializeToString())
    if hasattr(message_factory, "GetMessageClass"):  # protobuf 4.22 and later
        make = message_factory.GetMessageClass
    else:  # Debian 12's protobuf 3.21 (Python package 4.21)
        make = message_factory.MessageFactory(pool).GetPrototype
    for file in files:
        described = pool.FindFileByName(file.name)
        for name in described.message_types_by_name.values():
            _classes[name.full_name] = make(name)
