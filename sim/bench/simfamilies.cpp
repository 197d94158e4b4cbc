#include "sim/bench/simfamilies.h"

#include "sim/servocan/simservocandrive.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "sim/shuoke/simshuokecandevice.h"
#include "sim/shuoke/simshuokeserialdevice.h"

namespace dd {

const SimFamily &simFamily(Family family)
{
    // One line per family.
    static const QList<SimFamily> table{
        {Family::ServoCan, nullptr, &SimServoCanDrive::create, false},
        {Family::ServoModbus, &SimServoModbusDrive::create, nullptr, true},
        {Family::Shuoke, &SimShuokeSerialDevice::create, &SimShuokeCanDevice::create, false},
    };
    for (const SimFamily &f : table)
        if (f.family == family)
            return f;
    qFatal("simFamily: family %d has no simulator in sim/bench/simfamilies.cpp", int(family));
}

} // namespace dd
