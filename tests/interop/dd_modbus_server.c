/* A Modbus RTU server built on libmodbus, for DriveDesk's interop tests: software nobody on
 * this project wrote, answering DriveDesk's Modbus path.
 *
 *   dd_modbus_server DEVICE SLAVE BAUD
 *
 * Serves 0x0200 holding registers (register r starts as 1000 + r) as slave SLAVE on the
 * serial device DEVICE (the test gives it one end of a pty pair it bridges), 8N1. Prints
 * "LISTENING DEVICE" once the port is open, and after every write request one line
 * "REG <register> <value>" per register written (decimal), so that the test sees what the
 * server stored. Runs until killed. DD_MODBUS_DEBUG=1 turns on libmodbus's debug output. */

#include <errno.h>
#include <modbus.h>
#include <stdio.h>
#include <stdlib.h>

#define REGISTERS 0x0200

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: %s DEVICE SLAVE BAUD\n", argv[0]);
        return 2;
    }
    const int slave = atoi(argv[2]);
    const int baud = atoi(argv[3]);
    modbus_t *ctx = modbus_new_rtu(argv[1], baud, 'N', 8, 1);
    if (!ctx) {
        fprintf(stderr, "modbus_new_rtu: %s\n", modbus_strerror(errno));
        return 1;
    }
    modbus_set_slave(ctx, slave);
    /* After a bad frame libmodbus sleeps for the response timeout (default 0.5 s) and then
     * flushes its input; keep that short so that the host's retry finds it listening. */
    modbus_set_response_timeout(ctx, 0, 50000);
    if (getenv("DD_MODBUS_DEBUG"))
        modbus_set_debug(ctx, TRUE);
    modbus_mapping_t *map = modbus_mapping_new(0, 0, REGISTERS, 0);
    if (!map) {
        fprintf(stderr, "modbus_mapping_new: %s\n", modbus_strerror(errno));
        return 1;
    }
    for (int r = 0; r < REGISTERS; ++r)
        map->tab_registers[r] = (uint16_t)(1000 + r);
    if (modbus_connect(ctx) == -1) {
        fprintf(stderr, "modbus_connect %s: %s\n", argv[1], modbus_strerror(errno));
        return 1;
    }
    printf("LISTENING %s\n", argv[1]);
    fflush(stdout);

    uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
    for (;;) {
        const int rc = modbus_receive(ctx, query);
        if (rc <= 0)
            continue; /* not for us, bad CRC, timeout: keep listening */
        modbus_reply(ctx, query, rc, map);
        const int function = query[1];
        const int start = (query[2] << 8) | query[3];
        if (function == 0x06) {
            if (start < REGISTERS)
                printf("REG %d %d\n", start, map->tab_registers[start]);
        } else if (function == 0x10) {
            const int count = (query[4] << 8) | query[5];
            for (int i = 0; i < count && start + i < REGISTERS; ++i)
                printf("REG %d %d\n", start + i, map->tab_registers[start + i]);
        }
        fflush(stdout);
    }
}
