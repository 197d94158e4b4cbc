#!/usr/bin/python3
"""A servo-modbus drive served by pymodbus (Debian's python3-pymodbus 3.0), for the interop tests.

Usage: pymodbus_servo.py PORT BAUD ADDRESS[,ADDRESS...]

Each address holds registers 0x0000..0x009F: the monitor block (0x0000..0x0017) and the
parameters PA0..PA59 (0x0064..0x009F). PAn starts as 100 + n, PA2 (firmware) is 7051 and
PA51 the drive's address. Prints "ready" once it serves the port.
"""
import asyncio
import logging
import sys

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusServerContext, ModbusSlaveContext
from pymodbus.server.async_io import ModbusSerialServer
from pymodbus.transaction import ModbusRtuFramer


def registers(address):
    values = [0] * 0xA0
    for i in range(0x18):
        values[i] = 10 * i + 1
    for n in range(60):
        values[0x64 + n] = 100 + n
    values[0x64 + 2] = 7051
    values[0x64 + 51] = address
    return values


def main():
    port, baud, addresses = sys.argv[1], int(sys.argv[2]), [int(a) for a in sys.argv[3].split(",")]
    logging.basicConfig(level=logging.CRITICAL)
    slaves = {
        a: ModbusSlaveContext(hr=ModbusSequentialDataBlock(0, registers(a)), zero_mode=True) for a in addresses
    }
    context = ModbusServerContext(slaves=slaves, single=False)

    async def serve():
        server = ModbusSerialServer(context, framer=ModbusRtuFramer, port=port, baudrate=baud, bytesize=8,
                                    parity="N", stopbits=1, timeout=0.005, ignore_missing_slaves=True)
        await server.start()  # the port is open: requests from now on are heard
        print("ready", flush=True)
        await server.serve_forever()

    asyncio.run(serve())

if __name__ == "__main__":
    main()
