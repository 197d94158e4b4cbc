#include "cli/clihelp.h"

namespace dd {

QString CliHelp::general()
{
    // One text per section, so that a change to one section leaves the translations of the
    // others valid.
    return QStringList{usage(), linkOptions(), outputOptions(), commandList(), exitCodes(), simulator(), examples()}
        .join(QLatin1Char('\n'));
}

QString CliHelp::usage()
{
    return tr("Usage: drivedesk-cli [OPTIONS] COMMAND [ARGS]\n"
              "Commission servo and stepper drives from scripts.\n");
}

QString CliHelp::linkOptions()
{
    return tr("Link and drive:\n"
              "  --family servo-can|servo-modbus|shuoke   drive family (default: servo-can with\n"
              "                                 --can, servo-modbus otherwise)\n"
              "  --port DEVICE                  serial port, e.g. /dev/ttyUSB0 or COM3\n"
              "  --can PLUGIN:INTERFACE         CAN bus, e.g. socketcan:can0, virtualcan:can0\n"
              "  --baud N                       serial baud rate (default: the family's)\n"
              "  --bitrate N                    CAN bitrate (default: the family's)\n"
              "  --framing rtu|ascii|can|plc    shuoke framing (default: rtu on a port, can on CAN)\n"
              "  --address N                    the drive to talk to (default 1)\n"
              "  --timeout MS                   reply allowance beyond the wire time\n"
              "  --retries N                    extra attempts after a timeout\n"
              "  --dictionary FILE              parameter dictionary (names, ranges, units);\n"
              "                                 \"simulator\": the simulator's, with its loop gains\n"
              "  --option FAMILY.KEY=VALUE      a family setting where the protocol documents are\n"
              "                                 ambiguous, e.g. shuoke.checksum=twos-complement,\n"
              "                                 servo-modbus.positionRule=decimal10000 (repeatable;\n"
              "                                 see docs/cli.md)\n"
              "  --sim                          use the built-in simulator instead of hardware\n"
              "                                 (see \"Simulator\" below)\n")
        + tr("  --machine NAME                 the machine or project the drives belong to: the\n"
             "                                 verification journal keeps each machine's drives\n"
             "                                 apart (docs/record.md)\n");
}

QString CliHelp::outputOptions()
{
    return tr("Output:\n"
              "  --json                         one JSON document per command (JSON lines for\n"
              "                                 monitor); failures too, with \"ok\": false\n"
              "  --trace                        print every frame, timestamped, to stderr\n"
              "  --lang LANG                    language of messages, tables and help: en,\n"
              "                                 zh_CN or system (default: the locale, from\n"
              "                                 LANGUAGE, LC_ALL, LC_MESSAGES, LANG); --json\n"
              "                                 output is never translated\n"
              "  -h, --help                     this help; COMMAND --help for one command\n"
              "  -V, --version                  the version\n");
}

QString CliHelp::commandList()
{
    return tr("Commands:\n"
              "  scan [--from A] [--to B] [--bauds 9600,19200,...]\n"
              "                                 find drives: family, address, baud, firmware, state\n"
              "  info                           identity, firmware, state, alarm, capabilities\n"
              "  get PARAM ...                  read parameters; PARAM = 12, PA12, P12 or a name\n"
              "  set PARAM=VALUE ...            validate, write, read back, report verified or not\n"
              "  backup -o FILE [--changed-only] every readable parameter to a backup file\n"
              "  backup (--all | --address 1,2,5) -o DIR\n"
              "                                 one file per drive, FAMILY-ADDRESS.json, and index.json\n"
              "  diff FILE | diff A B           compare; A, B = FILE, drive, drive:ADDRESS or defaults\n"
              "  restore FILE [--dry-run] [--only PARAM,...] [--force]\n"
              "                                 write the differences, verify each\n"
              "  restore FILE (--all | --address 1,2,5) [--stop-on-failure]\n"
              "                                 the same to several drives, each at its address\n"
              "  ee set|rd|ba|rs|def            servo-modbus EEPROM operations; waits for them\n"
              "  monitor CHANNEL,... [--rate HZ] [--duration S] [-o FILE.csv]\n"
              "                                 sample live values (Ctrl-C ends)\n"
              "  jog SPEED [--duration S] [--enable]  run, then stop; Ctrl-C or any error stops at once\n"
              "  move (--by N | --to N) [--speed V] [--no-wait] [--enable]\n"
              "                                 move, and wait until the axis is at rest\n"
              "  stop [--emergency]             stop (emergency stop where the family has one)\n"
              "  enable on|off                  servo enable on or off\n"
              "  clear-alarm                    clear the alarm and check that it is gone\n"
              "  home [--positive] [--no-wait]  homing, negative direction first\n"
              "  channels                       the monitor channels this drive offers\n"
              "  capture CHANNEL,... [--trigger EXPR] [--pre 25%|0.1s] [--duration S]\n"
              "          [--mode single|auto] [--timeout S] -o RUN.ddrun\n"
              "                                 triggered capture to a run file\n"
              "  step velocity SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]\n"
              "  step position DISTANCE --speed V --max-travel N [-o RUN.ddrun]\n"
              "  step reversal SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]\n"
              "                                 step-response test within limits, with metrics\n"
              "  runs RUN.ddrun [RUN2.ddrun ...] metrics side by side, parameter differences\n"
              "  apply-run RUN.ddrun [--dry-run] [--force]\n"
              "                                 write the run's tuning parameters where they differ\n"
              "  spectrum RUN.ddrun CHANNEL [--peaks N]\n"
              "                                 a channel's spectrum and its peaks\n")
        + tr("  ping [--count N]               link health: turnaround, timeouts, errors, and\n"
             "                                 the timeout and gap to use; exit 1 if no answer\n")
        + tr("  report -o RECORD.pdf [--all] [--runs RUN.ddrun,...] [--header FILE.json]\n"
             "         [--json-out RECORD.json]\n"
             "                                 the commissioning record (PDF and JSON)\n");
}

QString CliHelp::exitCodes()
{
    return tr("Exit codes:\n"
              "  0  success\n"
              "  1  the drive or the protocol failed (timeout, exception, verify mismatch)\n"
              "  2  bad usage or bad input (nothing was sent)\n"
              "  3  the port or bus could not be opened\n");
}

QString CliHelp::simulator()
{
    return tr("Simulator:\n"
              "  --sim runs the command against simulated drives of --family inside this\n"
              "  process, with nothing plugged in: serial families on a pseudo-terminal,\n"
              "  CAN families on Qt's virtualcan bus. --port/--can are then not needed.\n"
              "  --sim-drives ADDR[@BAUD],...   the simulated drives (default: one at --address,\n"
              "                                 at --baud); e.g. --sim-drives 3@19200,7@38400\n"
              "  --sim-state FILE               keep the simulated drives' state (parameters,\n"
              "                                 EEPROM, position, alarm) in FILE between runs\n"
              "  --sim-motion                   the simulated drives move on their own (for\n"
              "                                 monitor demos; where the family's simulator can)\n"
              "  --sim-resonance-hz F           the simulated load resonates at F Hz (1..1000)\n"
              "  With --sim the simulator's dictionary is used: it names the simulator's own\n"
              "  loop gains in its \"tuning\" group (docs/tuning.md).\n");
}

QString CliHelp::examples()
{
    return tr("Examples:\n")
        + QStringLiteral("  drivedesk-cli --port /dev/ttyUSB0 scan --bauds 9600,19200,115200\n"
                         "  drivedesk-cli --port /dev/ttyUSB0 --address 3 set PA12=300 PA13=50\n"
                         "  drivedesk-cli --can socketcan:can0 --address 1 backup -o axis1.ddbackup\n"
                         "  drivedesk-cli --family shuoke --port COM3 --json monitor speed,position --rate 20\n"
                         "  drivedesk-cli --sim --family servo-can jog 100 --duration 2 --enable\n"
                         "  drivedesk-cli --lang zh_CN --sim get PA0 PA1\n");
}

QString CliHelp::command(const QString &name)
{
    if (name == QLatin1String("scan"))
        return tr("Usage: drivedesk-cli [OPTIONS] scan [--from A] [--to B] [--bauds 9600,19200,...]\n"
                  "Find the drives on the link. Without --bauds a serial scan tries --baud if given,\n"
                  "else the family's usual rates. Exit code 1 when no drive answered.\n");
    if (name == QLatin1String("info"))
        return tr("Usage: drivedesk-cli [OPTIONS] info\n"
                  "Identity, firmware, state, alarm and capabilities of the drive at --address.\n");
    if (name == QLatin1String("get"))
        return tr("Usage: drivedesk-cli [OPTIONS] get PARAM ...\n"
                  "Read parameters. PARAM is an index (12), PA12, P12, or a name from the\n"
                  "dictionary.\n");
    if (name == QLatin1String("set"))
        return tr("Usage: drivedesk-cli [OPTIONS] set PARAM=VALUE ...\n"
                  "Check every value against the dictionary (nothing is sent if one is bad),\n"
                  "write each, read it back and report whether it was verified.\n");
    if (name == QLatin1String("backup"))
        return tr("Usage: drivedesk-cli [OPTIONS] backup -o FILE [--changed-only]\n"
                  "       drivedesk-cli [OPTIONS] (--all | --address 1,2,5) backup -o DIR [--from A] [--to B]\n"
                  "Read every readable parameter and save them to a backup file (saved\n"
                  "atomically: an interrupted backup never leaves a half-written file).\n"
                  "--changed-only keeps only the settings that differ from the dictionary's\n"
                  "defaults (the file says so; its restore touches only those). Several drives\n"
                  "(--all: every drive a scan finds): one file per drive, FAMILY-ADDRESS.json,\n"
                  "and DIR/index.json; the exit code is the worst drive's.\n");
    if (name == QLatin1String("diff"))
        return tr("Usage: drivedesk-cli [OPTIONS] diff FILE\n"
                  "       drivedesk-cli [OPTIONS] diff A B\n"
                  "Compare the drive with a backup file, or any two sources: a backup file,\n"
                  "drive (the drive at --address), drive:ADDRESS or defaults. Two files need\n"
                  "no link. Sources of different families are refused. Exit code as diff(1):\n"
                  "0 equal, 1 different, 2 trouble (bad input, a drive that did not answer).\n");
    if (name == QLatin1String("restore"))
        return tr("Usage: drivedesk-cli [OPTIONS] restore FILE [--dry-run] [--only PARAM,...] [--force]\n"
                  "Write the parameters that differ from the file and verify each by reading it\n"
                  "back. The file is checked completely before anything is sent. A file from\n"
                  "another family is refused; from another firmware only with --force.\n"
                  "--dry-run shows what would be written. On failure the report says exactly\n"
                  "which parameters were written and which were not.\n"
                  "With --all (every drive a scan finds) or --address 1,2,5 the file goes to\n"
                  "each drive at its own address; communication settings are never copied\n"
                  "unless --only names them. --stop-on-failure: one drive after the other,\n"
                  "none after the first that fails. The exit code is the worst drive's.\n"
                  "restore DIR [--address 1,2,5]: a folder written by backup --all -o DIR put\n"
                  "back, every drive its index.json lists (or those of --address) from its own\n"
                  "file, at its address; each file is checked to be that drive's before anything\n"
                  "is sent.\n");
    if (name == QLatin1String("ee"))
        return tr("Usage: drivedesk-cli [OPTIONS] ee set|rd|ba|rs|def\n"
                  "servo-modbus EEPROM operations, waiting for completion:\n"
                  "  set  store the parameters to EEPROM      rd   reload them from EEPROM\n"
                  "  ba   copy to the backup area             rs   restore the backup area\n"
                  "  def  factory defaults\n");
    if (name == QLatin1String("monitor"))
        return tr("Usage: drivedesk-cli [OPTIONS] monitor CHANNEL,... [--rate HZ] [--duration S] [-o FILE.csv]\n"
                  "Sample live values at --rate (default 10 Hz) until --duration ends or Ctrl-C.\n"
                  "-o writes CSV: a header of channel names with units, time in seconds.\n"
                  "See `channels` for the channel names of a drive.\n");
    if (name == QLatin1String("jog"))
        return tr("Usage: drivedesk-cli [OPTIONS] jog SPEED [--duration S] [--enable]\n"
                  "Run at SPEED (negative: the other way) until --duration ends, Ctrl-C, SIGTERM\n"
                  "or any error, then stop. Without --duration it runs until Ctrl-C. A second\n"
                  "Ctrl-C sends an emergency stop where the family has one.\n"
                  "--enable: servo-can's motion commands switch the power stage on by themselves\n"
                  "and nobody can read whether it is on, so jog, move and step on servo-can run\n"
                  "only with --enable (exit 2, nothing sent, without it); the stage stays on.\n");
    if (name == QLatin1String("move"))
        return tr("Usage: drivedesk-cli [OPTIONS] move (--by N | --to N) [--speed V] [--no-wait] [--enable]\n"
                  "Relative (--by) or absolute (--to) move, in the drive's position units, at\n"
                  "--speed (the family's unit). Waits until the axis is at rest again (the link\n"
                  "and its keep-alives stay up meanwhile); --no-wait returns once the drive has\n"
                  "started. Ctrl-C stops the axis. --enable: as for jog (servo-can needs it).\n");
    if (name == QLatin1String("stop"))
        return tr("Usage: drivedesk-cli [OPTIONS] stop [--emergency]\n"
                  "Stop the axis; --emergency: an emergency stop where the family has one.\n");
    if (name == QLatin1String("enable"))
        return tr("Usage: drivedesk-cli [OPTIONS] enable on|off\n"
                  "Servo enable on or off.\n");
    if (name == QLatin1String("clear-alarm"))
        return tr("Usage: drivedesk-cli [OPTIONS] clear-alarm\n"
                  "Clear the alarm and read it again; exit code 1 if it is still there.\n");
    if (name == QLatin1String("home"))
        return tr("Usage: drivedesk-cli [OPTIONS] home [--positive] [--no-wait]\n"
                  "Search home, negative direction first (--positive: positive first), and wait\n"
                  "until the axis is at rest. Ctrl-C stops the axis.\n");
    if (name == QLatin1String("channels"))
        return tr("Usage: drivedesk-cli [OPTIONS] channels\n"
                  "The monitor channels this drive offers, with units.\n");
    if (name == QLatin1String("ping"))
        return tr("Usage: drivedesk-cli [OPTIONS] ping [--count N]\n"
                  "Ask the drive for its status N times (default 10), one request at a time, and\n"
                  "report the link's health: turnaround min / median / max, timeouts, checksum\n"
                  "errors, late or duplicated replies, retries, and the reply allowance (--timeout)\n"
                  "and gap between requests it recommends. Exit code 1 when the drive answered none.\n");
    if (name == QLatin1String("capture"))
        return tr("Usage: drivedesk-cli [OPTIONS] capture CHANNEL,... [--trigger EXPR] [--pre 25%|0.1s]\n"
                  "          [--duration S] [--mode single|auto] [--timeout S] [--notes TEXT] -o RUN.ddrun\n"
                  "EXPR: rise:CHANNEL:VALUE | fall:CHANNEL:VALUE | either:CHANNEL:VALUE\n"
                  "      | above:CHANNEL:VALUE | below:CHANNEL:VALUE | alarm | now (default)\n"
                  "Samples as fast as the link allows; --pre is the part of the record before the\n"
                  "trigger, with its unit: a percentage (25%) or seconds (0.1s) (default 0), as in\n"
                  "step; --duration the record (default 1 s); auto captures anyway\n"
                  "after --timeout seconds (default 1). Saves the samples and the drive's tuning\n"
                  "parameters (read from it) to RUN.ddrun (docs/tuning.md).\n");
    if (name == QLatin1String("step"))
        return tr("Usage: drivedesk-cli [OPTIONS] step velocity SPEED --duration S --max-speed V --max-travel N\n"
                  "       drivedesk-cli [OPTIONS] step position DISTANCE --speed V --max-travel N [--max-speed V]\n"
                  "       drivedesk-cli [OPTIONS] step reversal SPEED --duration S --max-speed V --max-travel N\n"
                  "          [--max-duration S] [--record S] [--pre 0.1s|25%] [--channels CH,...]\n"
                  "          [--no-return] [--counts-per-rev N] [--enable] [--notes TEXT] [-o RUN.ddrun]\n"
                  "velocity: run at SPEED for S seconds, then stop. position: move by DISTANCE at V.\n"
                  "reversal: run at +SPEED for S seconds, then at -SPEED for S seconds, then stop.\n"
                  "The limits are required (exit 2, nothing sent, without them): --max-speed (the\n"
                  "speed unit; a position step: 1.5 x --speed unless given), --max-travel from the\n"
                  "start position (pulses), --max-duration until the axis is at rest (default: the\n"
                  "step's time + 2 s; position 10 s). A test whose predicted travel or time (with\n"
                  "its stop; --counts-per-rev for r/min drives, default 10000) does not fit them is\n"
                  "refused, no motion sent. The captured speed and position are watched against\n"
                  "them (the travel early enough to stop inside it); an alarm, a limit, Ctrl-C, a\n"
                  "lost link, or a STOP or command from elsewhere (another master, the drive's\n"
                  "panel) stops the axis and ends the test with exit code 1; nothing moves after\n"
                  "it, and -o saves the record so far, marked aborted. The capture runs from --pre\n"
                  "(0.05s, or a percentage of the capture) before the motion command for --record\n"
                  "seconds (default: the step's time + 0.3 s; a position step: until the axis is\n"
                  "at rest, + 0.3 s).\n"
                  "A completed test returns to its start position, announced, under the same\n"
                  "limits and STOP (--no-return: it stays), prints\n"
                  "the metrics with their resolution or why they cannot be resolved, and saves the\n"
                  "run to RUN.ddrun with the tuning parameters read from the drive (docs/tuning.md).\n"
                  "--enable: as for jog (servo-can needs it).\n");
    if (name == QLatin1String("runs"))
        return tr("Usage: drivedesk-cli runs RUN.ddrun [RUN2.ddrun ...]\n"
                  "The runs' metrics side by side, and the tuning parameters that differ between\n"
                  "consecutive runs with what the metrics did. Reads files only.\n");
    if (name == QLatin1String("apply-run"))
        return tr("Usage: drivedesk-cli [OPTIONS] apply-run RUN.ddrun [--dry-run] [--force]\n"
                  "Write the tuning parameters the run was taken with (its snapshot) back to the\n"
                  "drive, as restore does: only those that differ from the drive, each read back\n"
                  "and reported verified or not. A run of another family, or whose parameters the\n"
                  "dictionary does not know as such, is refused (exit 2, nothing sent); another\n"
                  "firmware only with --force. --dry-run shows what would be written.\n");
    if (name == QLatin1String("spectrum"))
        return tr("Usage: drivedesk-cli spectrum RUN.ddrun CHANNEL [--peaks N] [--from HZ] [--between T1:T2]\n"
                  "The channel's amplitude spectrum (Hann window; resolution stated) and its N\n"
                  "highest peaks (default 5), at HZ and above with --from, of the samples from T1\n"
                  "to T2 seconds after the trigger with --between (e.g. after a step's own\n"
                  "transient, where its ringing shows a resonance). Reads files only.\n");
    if (name == QLatin1String("report"))
        return tr("Usage: drivedesk-cli [OPTIONS] report -o RECORD.pdf [--all] [--runs RUN.ddrun,...]\n"
                  "                     [--header FILE.json] [--json-out RECORD.json] [--page-size a4|letter]\n"
                  "The commissioning record of the drive at --address (--all: of every drive a scan\n"
                  "of the link finds): identity, firmware, link, the parameters that differ from the\n"
                  "dictionary's defaults (all of them in the appendix), the last restore or write\n"
                  "verification, alarms, link health and backup files, as a PDF in the language of\n"
                  "--lang, and the same as JSON whose SHA-256 the PDF prints (docs/record.md).\n"
                  "--all [--from A] [--to B]: the scan's address range (default: the family's).\n"
                  "--header: machine, customer, site, engineer, notes from a JSON file.\n"
                  "--runs RUN.ddrun,...: tuning runs (capture or step test files) shown with the drive\n"
                  "they were taken on: plot, metrics, parameter snapshot. A bad run file, or one of a\n"
                  "drive not in the record, exits 2 with the reason and writes nothing.\n");
    return general();
}

} // namespace dd
