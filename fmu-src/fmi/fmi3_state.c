/* FMI 3.0 FMU state snapshots and their serialization (adapters over snapshot.c). */
#include "fmi/instance.h"
#include "fmi3Functions.h"

fmi3Status fmi3GetFMUState(fmi3Instance instance, fmi3FMUState *state)
{
    return (fmi3Status)hg_get_state(instance, __func__, state);
}

fmi3Status fmi3SetFMUState(fmi3Instance instance, fmi3FMUState state)
{
    return (fmi3Status)hg_set_state(instance, __func__, state);
}

fmi3Status fmi3FreeFMUState(fmi3Instance instance, fmi3FMUState *state)
{
    return (fmi3Status)hg_free_state(instance, __func__, state);
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance instance, fmi3FMUState state, size_t *size)
{
    return (fmi3Status)hg_serialized_size(instance, __func__, state, size);
}

fmi3Status fmi3SerializeFMUState(fmi3Instance instance, fmi3FMUState state, fmi3Byte bytes[],
                                 size_t size)
{
    return (fmi3Status)hg_serialize(instance, __func__, state, bytes, size);
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance instance, const fmi3Byte bytes[], size_t size,
                                   fmi3FMUState *state)
{
    return (fmi3Status)hg_deserialize(instance, __func__, bytes, size, state);
}
