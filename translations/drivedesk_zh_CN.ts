<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>dd::AlarmDictionary</name>
    <message>
        <source>%1 is not a DriveDesk alarm table (format &quot;%2&quot;, expected &quot;%3&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: alarm table format version %2 is not supported (this DriveDesk reads version %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unknown drive family &quot;%2&quot; (known: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is an alarm table for %2 drives, not for %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;fallback.%2&quot; must contain %3 where the code goes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 must be an object (found %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: code %2 is listed twice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::BackupFile</name>
    <message>
        <source>The backup has no drive family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The dictionary does not belong to %1 drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive address %1 is outside 0 to 255</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter %1 is not in the %2 dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2. Is the folder writable and the disk not full?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2. The previous file, if any, is unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is larger than %2 bytes; it is not a file DriveDesk wrote</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;link&quot; has more than %2 entries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot; has an empty or too long name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot; must be a string (up to 256 characters), a number within ±2^53 or true/false (found %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a DriveDesk backup file (format &quot;%2&quot;, expected &quot;%3&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: backup format version %2 is not supported; this DriveDesk reads version %3. Use the DriveDesk version that wrote the file, or a newer one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unknown drive family &quot;%2&quot; (known: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a backup of a %2 drive, but the dictionary given is for %3 drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;created&quot; = &quot;%2&quot; is not an ISO 8601 date and time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;checksum&quot; must be &quot;sha256:&quot; followed by 64 lower-case hex digits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 must be an object (found %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: index %2 appears more than once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the checksum does not match the values: the file was changed or damaged after DriveDesk wrote it. Restore refuses it; use an intact copy.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: there is no parameter %2 for %3 drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: index %2 is %3 in the dictionary, not &quot;%4&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: access &quot;%2&quot; differs from the dictionary&apos;s &quot;%3&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a write-only value must be marked &quot;lastWritten&quot;: true</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &quot;lastWritten&quot; is only allowed on write-only values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: value %2 is outside the allowed range %3 to %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This backup is of a %1 drive; it cannot be restored to a %2 drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The backup was taken from firmware %1, but the drive&apos;s firmware version is unknown. Parameters may differ between firmware versions: compare them first, then force the restore if you are sure.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The backup does not record a firmware version; the drive has firmware %1. Compare the parameters first, then force the restore if you are sure.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The backup was taken from firmware %1; the drive has firmware %2. Parameters may differ between firmware versions: compare them first, then force the restore if you are sure.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::BusTreeWidget</name>
    <message>
        <source>Link lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1, address %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh identity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::CanLink</name>
    <message>
        <source>The CAN link was destroyed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot create CAN device %1:%2: %3. Available plugins: %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot connect to CAN interface %1: %2. Is the interface up (ip link set %3 up type can bitrate %4)?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CAN link %1 was closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CAN link is not open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write to CAN interface %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No reply on %1 within %2 ms after %3 attempts. Check the station number, the bitrate and the bus termination.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CAN bus %1 went away. Check the adapter and the bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN interface %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::ConnectDialog</name>
    <message>
        <source>%1 kbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No CAN plugin is installed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The %1 plugin reports no interface; type its name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RTU (binary)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ASCII</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC mode (Modbus registers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a serial port, or type its name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a CAN plugin and an interface.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Serial port (RS485 / RS232)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;AN bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Adapters are listed as they are plugged in. Virtual ports: links to pseudo-terminals in the temp directory (drivedesk-sim --link).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Family default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Try all common baud rates when scanning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P&amp;lugin:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Interface:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B&amp;itrate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Family:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F&amp;raming:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shuoke drives only: how the drive is set to talk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect automatically</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detect tries each family in turn (serial: servo-modbus, then shuoke RTU and ASCII; CAN: servo-can, then shuoke) and keeps the first that finds a drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;can for drives after connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Addresses:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;onnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::ConnectRequest</name>
    <message>
        <source>auto-detect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::ConnectionController</name>
    <message>
        <source>Scanning %1 for %2 drives, addresses %3–%4…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1 (%2)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(try %1 of %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Found %n drive(s).</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Scan cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No drive answered. Check the wiring and termination, the baud rate or bitrate, the family and the address range.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::DisplayText</name>
    <message>
        <source>Servo (CAN)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Servo (Modbus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shuoke stepper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 #%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No alarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::Drive</name>
    <message>
        <source>No parameter to write.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The %1 drive family has no &quot;%2&quot; operation.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::DriveConnection</name>
    <message>
        <source>The %1 family is not available in this build.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::DriveHub</name>
    <message>
        <source>The connection is closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no drive at address %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The operation was not started.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::DriveWorkspace</name>
    <message>
        <source>Select a drive in the bus tree.

No drive yet? Use File → Connect… to open a serial port or a CAN interface and scan it, or File → Demo bench to try DriveDesk with simulated drives.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::JsonFieldReader</name>
    <message>
        <source>%1: field &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be an integer (found %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>holds a number too large to be exact (the limit is ±%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a whole number (found %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: required field &quot;%2&quot; is missing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 = %2 is outside the allowed range %3 to %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a number (found %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be a string (found %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>is longer than %1 characters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must not be empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be true or false (found %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be an object (found %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>must be an array (found %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>has more than %1 entries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a language code (use e.g. &quot;en&quot;, &quot;zh&quot;, &quot;zh_CN&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 needs a non-empty &quot;%2&quot; text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unknown field &quot;%2&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is larger than %2 bytes; it is not a file DriveDesk wrote</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (is the file empty or truncated?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not valid JSON: %2 at byte %3%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the top level must be a JSON object</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::MainWindow</name>
    <message>
        <source>STOP sent to all drives.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Demo bench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a drive first: %1 is opened in one of its tabs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About DriveDesk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;DriveDesk %1&lt;/h3&gt;&lt;p&gt;Commissioning and tuning workbench for servo and stepper drives over RS485 / RS232 and CAN.&lt;/p&gt;&lt;p&gt;Drive families: servo-can, servo-modbus, shuoke.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DriveDesk — commissioning workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Recent files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a serial port or a CAN interface and scan it for drives (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the selected connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disconnect &amp;all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>De&amp;mo bench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start simulated drives of every family and connect to them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About DriveDesk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;System language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Bus tree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Main tool bar</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::OverviewPanel</name>
    <message>
        <source>Overview</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capabilities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Family:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Firmware:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Communication:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Power stage:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last update:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Function</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Available</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the identity and the status of the drive again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Online</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not polled yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::ParameterDictionary</name>
    <message>
        <source>%1 must be an object (found %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: key &quot;%2&quot; must start with a letter and hold only letters, digits, &apos;_&apos;, &apos;.&apos; and &apos;-&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: key &quot;%2&quot; names parameter %3 but the index is %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;type&quot; = &quot;%2&quot; is not one of uint8, int16, uint16, int32, uint32</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;access&quot; = &quot;%2&quot; is not one of rw, ro, wo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: min %2 is greater than max %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the range %2 to %3 does not fit the type %4 (%5 to %6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: default %2 is outside the range %3 to %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a write-only parameter cannot have a readCommand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a readable shuoke parameter needs a readCommand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a servo-modbus parameter needs a register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: models[%2] must be a model name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a DriveDesk parameter dictionary (format &quot;%2&quot;, expected &quot;%3&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: dictionary format version %2 is not supported (this DriveDesk reads version %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unknown drive family &quot;%2&quot; (known: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is a dictionary for %2 drives, not for %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: field &quot;valueType&quot; = &quot;%2&quot; is not one of uint8, int16, uint16, int32, uint32</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the dictionary has no parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: index %2 is already used by %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: key &quot;%2&quot; is already used (keys are case-insensitive)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: register %2 is already used by %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown parameter &quot;%1&quot; for %2 drives: give a number (12), a key (%3) or a name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no parameter %1 for %2 drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 is outside the allowed range %3 to %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 %5 is outside the allowed range %3 to %4 %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is read-only: the drive does not accept a new value</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::ParameterDiff</name>
    <message>
        <source>Parameter %1 has no value in the backup file, so it cannot be restored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter %1 is read-only, so it cannot be restored</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::RecentFiles</name>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Clear list</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::ScanProgressWidget</name>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) found</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1 left · %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::SerialLink</name>
    <message>
        <source>The serial link was destroyed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open serial port %1: %2. Check the device name, that no other program is using it, and that you may access it (dialout group).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The serial port %1 was closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The serial port is not open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive&apos;s reply on %1 failed its checksum. Check the cable shielding, the bus termination and the baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No reply on %1 within %2 ms. Check the drive address, the baud rate, the wiring (A/B swapped?) and the bus termination.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The serial port %1 failed (%2). Was the adapter unplugged?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::SerialPortWatcher</name>
    <message>
        <source>Virtual port (pseudo-terminal)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::StatusBarWidget</name>
    <message>
        <source>Not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link lost: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n link(s) open</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1 frames/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Errors: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retries: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset error and retry counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames sent and received per second, all links</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discarded frames (bad checksum, garbage, late replies), lost links and failed operations. Right-click to reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Requests sent again after a timeout or a corrupt reply</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::StopAction</name>
    <message>
        <source>STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop all drives on all connections (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> or </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::servocan</name>
    <message>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>r/min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pulses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Torque command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotor position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input IO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output IO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus voltage</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::servomodbus</name>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position, low part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position, high part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command position, low part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command position, high part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position error, low part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position error, high part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Torque</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pulse frequency</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Torque command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotor absolute position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input terminals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output terminals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder signals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phase A current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phase C current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reserved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Store parameters to EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reload parameters from EEPROM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back up parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore the parameter backup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restore factory defaults</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>dd::shuoke</name>
    <message>
        <source>Handshake</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Query address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get baud code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set baud code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set start speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get start speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set maximum speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get maximum speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set stop speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get stop speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set deceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get deceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set homing speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get homing speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move relative (signed pulses)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move relative (direction + 24-bit pulses)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run at constant speed (signed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run at constant speed (direction + 24-bit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change speed while running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Query speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Query absolute position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear absolute position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Query relative position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear relative position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Query status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decelerate to stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set PLC mapping base</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set IO substitution entry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read IO substitution entry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read inputs IO1..IO5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read pulse, direction, enable, F1, F2 inputs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set speed step F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Increase speed by F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Decrease speed by F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skip CRC check of received commands</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fixed-length replies</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN frame format</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN bitrate code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serial to CAN test echo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN to serial test echo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home (variant 2) / S-curve move (signed pulses)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home (variant 3) / S-curve move (direction + 24-bit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed loop: move by feedback pulses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed loop: move by geared pulses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed loop: move to absolute position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed loop: read absolute position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed loop: set or clear absolute position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed loop: read relative position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed loop: set or clear relative position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Accumulated-error correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set gear numerator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get gear numerator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set gear denominator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Get gear denominator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder A/B error tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum pulses without encoder signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Receive timeout or wrong data length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checksum error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command does not support broadcast</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
