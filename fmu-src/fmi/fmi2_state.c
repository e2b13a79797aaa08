/* FMI 2.0 FMU state snapshots and their serialization (adapters over snapshot.c). */
#include "fmi/instance.h"
#include "fmi2Functions.h"

fmi2Status fmi2GetFMUstate(fmi2Component comp, fmi2FMUstate *state)
{
    return (fmi2Status)hg_get_state(comp, __func__, state);
}

fmi2Status fmi2SetFMUstate(fmi2Component comp, fmi2FMUstate state)
{
    return (fmi2Status)hg_set_state(comp, __func__, state);
}

fmi2Status fmi2FreeFMUstate(fmi2Component comp, fmi2FMUstate *state)
{
    return (fmi2Status)hg_free_state(comp, __func__, state);
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component comp, fmi2FMUstate state, size_t *size)
{
    return (fmi2Status)hg_serialized_size(comp, __func__, state, size);
}

fmi2Status fmi2SerializeFMUstate(fmi2Component comp, fmi2FMUstate state, fmi2Byte bytes[],
                                 size_t size)
{
    return (fmi2Status)hg_serialize(comp, __func__, state, bytes, size);
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component comp, const fmi2Byte bytes[], size_t size,
                                   fmi2FMUstate *state)
{
    return (fmi2Status)hg_deserialize(comp, __func__, bytes, size, state);
}
