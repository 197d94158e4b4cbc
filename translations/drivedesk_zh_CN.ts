<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>dd::AlarmDictionary</name>
    <message>
        <source>%1 is not a DriveDesk alarm table (format &quot;%2&quot;, expected &quot;%3&quot;)</source>
        <translation>%1 不是 DriveDesk 报警表（格式为“%2”，应为“%3”）</translation>
    </message>
    <message>
        <source>%1: alarm table format version %2 is not supported (this DriveDesk reads version %3)</source>
        <translation>%1：不支持报警表格式版本 %2（本版 DriveDesk 读取版本 %3）</translation>
    </message>
    <message>
        <source>%1: unknown drive family &quot;%2&quot; (known: %3)</source>
        <translation>%1：未知的驱动器系列“%2”（已知：%3）</translation>
    </message>
    <message>
        <source>%1 is an alarm table for %2 drives, not for %3</source>
        <translation>%1 是 %2 驱动器的报警表，不适用于 %3</translation>
    </message>
    <message>
        <source>%1: field &quot;fallback.%2&quot; must contain %3 where the code goes</source>
        <translation>%1：字段“fallback.%2”必须在代码位置包含 %3</translation>
    </message>
    <message>
        <source>%1 must be an object (found %2)</source>
        <translation>%1 必须是对象（实际为 %2）</translation>
    </message>
    <message>
        <source>%1: code %2 is listed twice</source>
        <translation>%1：代码 %2 重复出现</translation>
    </message>
    <message>
        <source>Alarm %1</source>
        <translation>报警 %1</translation>
    </message>
</context>
<context>
    <name>dd::AlarmsPanel</name>
    <message>
        <source>Alarms</source>
        <translation>报警</translation>
    </message>
    <message>
        <source>No alarm</source>
        <translation>无报警</translation>
    </message>
    <message>
        <source>Cannot write %1: %2.</source>
        <translation>无法写入 %1：%2。</translation>
    </message>
    <message>
        <source>Export alarm history</source>
        <translation>导出报警历史</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation>尚未读取。</translation>
    </message>
    <message>
        <source>Alarm %1</source>
        <translation>报警 %1</translation>
    </message>
    <message>
        <source>The drive reports no alarm.</source>
        <translation>驱动器未报告报警。</translation>
    </message>
    <message>
        <source>What to check: %1</source>
        <translation>检查建议：%1</translation>
    </message>
    <message>
        <source>Alarm cleared</source>
        <translation>报警已清除</translation>
    </message>
    <message>
        <source>Waiting for the drive&apos;s description…</source>
        <translation>正在等待驱动器信息…</translation>
    </message>
    <message>
        <source>Ask the drive for its current alarm code</source>
        <translation>向驱动器读取当前报警代码</translation>
    </message>
    <message>
        <source>Reset the drive&apos;s alarm (the cause must be gone)</source>
        <translation>复位驱动器报警（须先排除报警原因）</translation>
    </message>
    <message>
        <source>Current alarm</source>
        <translation>当前报警</translation>
    </message>
    <message>
        <source>History</source>
        <translation>历史记录</translation>
    </message>
    <message>
        <source>&amp;Read alarm</source>
        <translation>读取报警(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Clear alarm</source>
        <translation>清除报警(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>导出(&amp;E)…</translation>
    </message>
    <message>
        <source>Clear &amp;list</source>
        <translation>清空列表(&amp;L)</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>代码</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <source>the alarm table knows no code %1: see the drive&apos;s manual. To name it here, put your own table at %2 (format: docs/dictionaries.md).</source>
        <translation>报警表中没有代码 %1：请查阅驱动器说明书。如需在此显示其名称，请将自己的报警表放在 %2（格式见 docs/dictionaries.md）。</translation>
    </message>
</context>
<context>
    <name>dd::BackupFile</name>
    <message>
        <source>The backup has no drive family</source>
        <translation>备份中没有驱动器系列</translation>
    </message>
    <message>
        <source>The dictionary does not belong to %1 drives</source>
        <translation>该参数字典不属于 %1 驱动器</translation>
    </message>
    <message>
        <source>Drive address %1 is outside 0 to 255</source>
        <translation>驱动器地址 %1 超出 0 到 255</translation>
    </message>
    <message>
        <source>Parameter %1 is not in the %2 dictionary</source>
        <translation>参数 %1 不在 %2 参数字典中</translation>
    </message>
    <message>
        <source>the backup</source>
        <translation>备份</translation>
    </message>
    <message>
        <source>Cannot write %1: %2. Is the folder writable and the disk not full?</source>
        <translation>无法写入 %1：%2。请检查文件夹是否可写、磁盘是否已满。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2. The previous file, if any, is unchanged.</source>
        <translation>无法写入 %1：%2。原有文件（如有）保持不变。</translation>
    </message>
    <message>
        <source>%1 is larger than %2 bytes; it is not a file DriveDesk wrote</source>
        <translation>%1 大于 %2 字节，不是 DriveDesk 生成的文件</translation>
    </message>
    <message>
        <source>%1: field &quot;link&quot; has more than %2 entries</source>
        <translation>%1：字段“link”超过 %2 项</translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot; has an empty or too long name</source>
        <translation>%1：字段“%2”的名称为空或过长</translation>
    </message>
    <message>
        <source>%1: field &quot;%2&quot; must be a string (up to 256 characters), a number within ±2^53 or true/false (found %3)</source>
        <translation>%1：字段“%2”必须是字符串（最多 256 个字符）、±2^53 以内的数值或 true/false（实际为 %3）</translation>
    </message>
    <message>
        <source>%1 is not a DriveDesk backup file (format &quot;%2&quot;, expected &quot;%3&quot;)</source>
        <translation>%1 不是 DriveDesk 备份文件（格式为“%2”，应为“%3”）</translation>
    </message>
    <message>
        <source>%1: backup format version %2 is not supported; this DriveDesk reads version %3. Use the DriveDesk version that wrote the file, or a newer one.</source>
        <translation>%1：不支持备份格式版本 %2，本版 DriveDesk 读取版本 %3。请使用生成该文件的 DriveDesk 版本或更新版本。</translation>
    </message>
    <message>
        <source>%1: unknown drive family &quot;%2&quot; (known: %3)</source>
        <translation>%1：未知的驱动器系列“%2”（已知：%3）</translation>
    </message>
    <message>
        <source>%1 is a backup of a %2 drive, but the dictionary given is for %3 drives</source>
        <translation>%1 是 %2 驱动器的备份，但所给参数字典适用于 %3 驱动器</translation>
    </message>
    <message>
        <source>%1: field &quot;created&quot; = &quot;%2&quot; is not an ISO 8601 date and time</source>
        <translation>%1：字段“created” = “%2”不是 ISO 8601 日期时间</translation>
    </message>
    <message>
        <source>%1: field &quot;checksum&quot; must be &quot;sha256:&quot; followed by 64 lower-case hex digits</source>
        <translation>%1：字段“checksum”必须是“sha256:”后跟 64 位小写十六进制数字</translation>
    </message>
    <message>
        <source>%1 must be an object (found %2)</source>
        <translation>%1 必须是对象（实际为 %2）</translation>
    </message>
    <message>
        <source>%1: index %2 appears more than once</source>
        <translation>%1：序号 %2 出现多次</translation>
    </message>
    <message>
        <source>%1: the checksum does not match the values: the file was changed or damaged after DriveDesk wrote it. Restore refuses it; use an intact copy.</source>
        <translation>%1：校验和与参数值不符，文件在 DriveDesk 写入后被修改或已损坏。无法用于恢复，请使用完好的副本。</translation>
    </message>
    <message>
        <source>%1: there is no parameter %2 for %3 drives</source>
        <translation>%1：%3 驱动器没有参数 %2</translation>
    </message>
    <message>
        <source>%1: index %2 is %3 in the dictionary, not &quot;%4&quot;</source>
        <translation>%1：序号 %2 在参数字典中是 %3，而不是“%4”</translation>
    </message>
    <message>
        <source>%1: access &quot;%2&quot; differs from the dictionary&apos;s &quot;%3&quot;</source>
        <translation>%1：访问属性“%2”与参数字典中的“%3”不同</translation>
    </message>
    <message>
        <source>%1: a write-only value must be marked &quot;lastWritten&quot;: true</source>
        <translation>%1：只写参数值必须标注 &quot;lastWritten&quot;: true</translation>
    </message>
    <message>
        <source>%1: &quot;lastWritten&quot; is only allowed on write-only values</source>
        <translation>%1：“lastWritten”只能用于只写参数值</translation>
    </message>
    <message>
        <source>%1: value %2 is outside the allowed range %3 to %4</source>
        <translation>%1：数值 %2 超出允许范围 %3 到 %4</translation>
    </message>
    <message>
        <source>This backup is of a %1 drive; it cannot be restored to a %2 drive</source>
        <translation>此备份来自 %1 驱动器，不能恢复到 %2 驱动器</translation>
    </message>
    <message>
        <source>The backup was taken from firmware %1, but the drive&apos;s firmware version is unknown. Parameters may differ between firmware versions: compare them first, then force the restore if you are sure.</source>
        <translation>备份取自固件 %1，但驱动器的固件版本未知。不同固件版本的参数可能不同：请先比较参数，确认无误后再强制恢复。</translation>
    </message>
    <message>
        <source>The backup does not record a firmware version; the drive has firmware %1. Compare the parameters first, then force the restore if you are sure.</source>
        <translation>备份未记录固件版本，驱动器固件为 %1。请先比较参数，确认无误后再强制恢复。</translation>
    </message>
    <message>
        <source>The backup was taken from firmware %1; the drive has firmware %2. Parameters may differ between firmware versions: compare them first, then force the restore if you are sure.</source>
        <translation>备份取自固件 %1，驱动器固件为 %2。不同固件版本的参数可能不同：请先比较参数，确认无误后再强制恢复。</translation>
    </message>
    <message>
        <source>%1: field &quot;scope&quot; must be &quot;all&quot; or &quot;%2&quot; (found &quot;%3&quot;)</source>
        <translation>%1：字段 &quot;scope&quot; 必须是 &quot;all&quot; 或 &quot;%2&quot;（实际为 &quot;%3&quot;）</translation>
    </message>
</context>
<context>
    <name>dd::BusTreeWidget</name>
    <message numerus="yes">
        <source>%n drive(s)</source>
        <translation>
            <numerusform>%n 台驱动器</numerusform>
        </translation>
    </message>
    <message>
        <source>%1, address %2</source>
        <translation>%1，地址 %2</translation>
    </message>
    <message>
        <source>Model: %1</source>
        <translation>型号：%1</translation>
    </message>
    <message>
        <source>Refresh identity</source>
        <translation>重新读取设备信息</translation>
    </message>
    <message>
        <source>Scan again</source>
        <translation>重新扫描</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开连接</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>link lost</source>
        <translation>连接中断</translation>
    </message>
    <message>
        <source>%1 — %2 (%3)</source>
        <translation>%1 — %2（%3）</translation>
    </message>
    <message numerus="yes">
        <source>Apply backup to %n drive(s)…</source>
        <translation>
            <numerusform>将备份应用到 %n 台驱动器…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Copy parameters from drive %1 to %n drive(s)…</source>
        <translation>
            <numerusform>将驱动器 %1 的参数复制到 %n 台驱动器…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Compare %n drive(s)…</source>
        <translation>
            <numerusform>比较 %n 台驱动器…</numerusform>
        </translation>
    </message>
    <message>
        <source>#%1 %2</source>
        <translation>#%1 %2</translation>
    </message>
</context>
<context>
    <name>dd::CanLink</name>
    <message>
        <source>The CAN link was destroyed.</source>
        <translation>CAN 连接已被销毁。</translation>
    </message>
    <message>
        <source>Cannot create CAN device %1:%2: %3. Available plugins: %4.</source>
        <translation>无法创建 CAN 设备 %1:%2：%3。可用插件：%4。</translation>
    </message>
    <message>
        <source>Cannot connect to CAN interface %1: %2. Is the interface up (ip link set %3 up type can bitrate %4)?</source>
        <translation>无法连接 CAN 接口 %1：%2。接口是否已启用（ip link set %3 up type can bitrate %4）？</translation>
    </message>
    <message>
        <source>The CAN link %1 was closed.</source>
        <translation>CAN 连接 %1 已关闭。</translation>
    </message>
    <message>
        <source>The CAN link is not open.</source>
        <translation>CAN 连接未打开。</translation>
    </message>
    <message>
        <source>Cannot write to CAN interface %1: %2</source>
        <translation>无法向 CAN 接口 %1 发送：%2</translation>
    </message>
    <message>
        <source>No reply on %1 within %2 ms after %3 attempts. Check the station number, the bitrate and the bus termination.</source>
        <translation>%1 上尝试 %3 次，%2 ms 内均无应答。请检查站号、波特率和总线终端电阻。</translation>
    </message>
    <message>
        <source>The CAN bus %1 went away. Check the adapter and the bus.</source>
        <translation>CAN 总线 %1 已断开。请检查适配器和总线。</translation>
    </message>
    <message>
        <source>CAN interface %1: %2</source>
        <translation>CAN 接口 %1：%2</translation>
    </message>
</context>
<context>
    <name>dd::ChannelSampler</name>
    <message>
        <source>The drive is gone; sampling stopped.</source>
        <translation>驱动器已不在；采样已停止。</translation>
    </message>
</context>
<context>
    <name>dd::ConnectDialog</name>
    <message>
        <source>%1 kbit/s</source>
        <translation>%1 kbit/s</translation>
    </message>
    <message>
        <source>No CAN plugin is installed.</source>
        <translation>未安装 CAN 插件。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>The %1 plugin reports no interface; type its name.</source>
        <translation>%1 插件未报告任何接口，请输入接口名称。</translation>
    </message>
    <message>
        <source>Choose a serial port, or type its name.</source>
        <translation>请选择串口，或输入串口名称。</translation>
    </message>
    <message>
        <source>Choose a CAN plugin and an interface.</source>
        <translation>请选择 CAN 插件和接口。</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>通讯链路</translation>
    </message>
    <message>
        <source>&amp;Serial port (RS485 / RS232)</source>
        <translation>串口（RS485 / RS232）(&amp;S)</translation>
    </message>
    <message>
        <source>C&amp;AN bus</source>
        <translation>CAN 总线(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Port:</source>
        <translation>端口(&amp;P)：</translation>
    </message>
    <message>
        <source>Adapters are listed as they are plugged in. Virtual ports: links to pseudo-terminals in the temp directory (drivedesk-sim --link).</source>
        <translation>插入适配器后会自动列出。虚拟端口：临时目录中指向伪终端的链接（drivedesk-sim --link）。</translation>
    </message>
    <message>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <source>Family default</source>
        <translation>系列默认值</translation>
    </message>
    <message>
        <source>Try all common baud rates when scanning</source>
        <translation>扫描时尝试所有常用波特率</translation>
    </message>
    <message>
        <source>P&amp;lugin:</source>
        <translation>插件(&amp;L)：</translation>
    </message>
    <message>
        <source>&amp;Interface:</source>
        <translation>接口(&amp;I)：</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <source>&amp;Family:</source>
        <translation>系列(&amp;F)：</translation>
    </message>
    <message>
        <source>F&amp;raming:</source>
        <translation>帧格式(&amp;R)：</translation>
    </message>
    <message>
        <source>Shuoke drives only: how the drive is set to talk</source>
        <translation>仅适用于硕科驱动器：驱动器设定的通讯方式</translation>
    </message>
    <message>
        <source>Detect automatically</source>
        <translation>自动识别</translation>
    </message>
    <message>
        <source>Detect tries each family in turn (serial: servo-modbus, then shuoke RTU and ASCII; CAN: servo-can, then shuoke) and keeps the first that finds a drive.</source>
        <translation>自动识别会依次尝试各系列（串口：先 servo-modbus，再 shuoke RTU 和 ASCII；CAN：先 servo-can，再 shuoke），采用第一个找到驱动器的系列。</translation>
    </message>
    <message>
        <source>S&amp;can for drives after connecting</source>
        <translation>连接后扫描驱动器(&amp;C)</translation>
    </message>
    <message>
        <source>Addresses:</source>
        <translation>地址范围：</translation>
    </message>
    <message>
        <source>C&amp;onnect</source>
        <translation>连接(&amp;O)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Bi&amp;trate:</source>
        <translation>波特率(&amp;T)：</translation>
    </message>
    <message>
        <source>Probe ti&amp;meout:</source>
        <translation>应答超时(&amp;M)：</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Automatic (fast, direct RS485 only)</source>
        <translation>自动（较快，仅适用于直连 RS485）</translation>
    </message>
    <message>
        <source>How long to wait for each address to answer. USB adapters add up to 16 ms of latency: keep 50 ms or more unless the port is a native RS485 interface.</source>
        <translation>每个地址等待应答的时间。USB 转换器会增加最多 16 ms 的延迟：除非是原生 RS485 接口，否则请保持 50 ms 或以上。</translation>
    </message>
    <message>
        <source>No serial port was found. Plug in the USB adapter (it appears here within a second), or try DriveDesk on simulated drives.</source>
        <translation>没有找到串口。请插入 USB 转换器（一秒内会出现在这里），或在模拟驱动器上试用 DriveDesk。</translation>
    </message>
    <message>
        <source>Start the &amp;demo bench</source>
        <translation>启动演示试验台(&amp;D)</translation>
    </message>
</context>
<context>
    <name>dd::ConnectRequest</name>
    <message>
        <source>auto-detect</source>
        <translation>自动识别</translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation>%1，%2</translation>
    </message>
    <message>
        <source>Unknown family &quot;%1&quot;; use one of: %2, detect.</source>
        <translation>未知系列“%1”，请使用：%2、detect。</translation>
    </message>
    <message>
        <source>Unknown framing &quot;%1&quot;; use one of: %2.</source>
        <translation>未知帧格式“%1”，请使用：%2。</translation>
    </message>
</context>
<context>
    <name>dd::ConnectionController</name>
    <message>
        <source>Scanning %1 for %2 drives, addresses %3–%4…</source>
        <translation>正在 %1 上扫描%2驱动器，地址 %3–%4…</translation>
    </message>
    <message>
        <source>Opening %1 (%2)…</source>
        <translation>正在打开 %1（%2）…</translation>
    </message>
    <message>
        <source>(try %1 of %2)</source>
        <translation>（第 %1 次，共 %2 次）</translation>
    </message>
    <message numerus="yes">
        <source>Found %n drive(s).</source>
        <translation>
            <numerusform>找到 %n 台驱动器。</numerusform>
        </translation>
    </message>
    <message>
        <source>Scan cancelled.</source>
        <translation>扫描已取消。</translation>
    </message>
    <message>
        <source>Connected.</source>
        <translation>已连接。</translation>
    </message>
    <message>
        <source>No drive answered. Check the wiring and termination, the baud rate or bitrate, the family and the address range.</source>
        <translation>没有驱动器应答。请检查接线和终端电阻、波特率、驱动器系列以及地址范围。</translation>
    </message>
</context>
<context>
    <name>dd::CsvWriter</name>
    <message>
        <source>Cannot write the CSV file %1: %2. Check that the folder exists and is writable.</source>
        <translation>无法写入 CSV 文件 %1：%2。请检查文件夹是否存在且可写。</translation>
    </message>
    <message>
        <source>Writing the CSV file %1 failed: %2. Is the disk full?</source>
        <translation>写入 CSV 文件 %1 失败：%2。磁盘是否已满？</translation>
    </message>
    <message>
        <source>The CSV file is not open.</source>
        <translation>CSV 文件未打开。</translation>
    </message>
    <message>
        <source>The sample time is not a valid number.</source>
        <translation>采样时间不是有效数值。</translation>
    </message>
</context>
<context>
    <name>dd::DisplayText</name>
    <message>
        <source>%1 #%2</source>
        <translation>%1 #%2</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Offline</source>
        <translation>离线</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Enabled</source>
        <translation>已使能</translation>
    </message>
    <message>
        <source>Disabled</source>
        <translation>未使能</translation>
    </message>
    <message>
        <source>Alarm %1</source>
        <translation>报警 %1</translation>
    </message>
    <message>
        <source>No alarm</source>
        <translation>无报警</translation>
    </message>
    <message>
        <source>Read parameters</source>
        <translation>读取参数</translation>
    </message>
    <message>
        <source>Write parameters</source>
        <translation>写入参数</translation>
    </message>
    <message>
        <source>Live monitor</source>
        <translation>实时监控</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>点动</translation>
    </message>
    <message>
        <source>Relative move</source>
        <translation>相对运动</translation>
    </message>
    <message>
        <source>Absolute move</source>
        <translation>绝对运动</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>回零</translation>
    </message>
    <message>
        <source>Set position</source>
        <translation>设置位置</translation>
    </message>
    <message>
        <source>Enable / disable</source>
        <translation>使能 / 取消使能</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>Read alarm</source>
        <translation>读取报警</translation>
    </message>
    <message>
        <source>Clear alarm</source>
        <translation>清除报警</translation>
    </message>
    <message>
        <source>EEPROM operations</source>
        <translation>EEPROM 操作</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>运动中</translation>
    </message>
    <message>
        <source>at rest</source>
        <translation>静止</translation>
    </message>
    <message>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <translation>%1 [%2]</translation>
    </message>
</context>
<context>
    <name>dd::Drive</name>
    <message>
        <source>No parameter to write.</source>
        <translation>没有要写入的参数。</translation>
    </message>
    <message>
        <source>The %1 drive family has no &quot;%2&quot; operation.</source>
        <translation>%1 驱动器系列没有“%2”操作。</translation>
    </message>
    <message>
        <source>%1 is given twice. Nothing was written.</source>
        <translation>%1 给出了两次。未写入任何参数。</translation>
    </message>
    <message>
        <source>The jog lease was not renewed within %1 ms.</source>
        <translation>点动租约在 %1 ms 内未续期。</translation>
    </message>
    <message>
        <source>The axis was stopped by a stop command.</source>
        <translation>轴已由停止命令停止。</translation>
    </message>
    <message>
        <source>%1 The drive&apos;s own watchdog stops the axis %2 ms after it last heard from DriveDesk.</source>
        <translation>%1 驱动器自身的看门狗会在最后一次收到 DriveDesk 消息 %2 ms 后停止该轴。</translation>
    </message>
    <message>
        <source>%1 This drive has no watchdog: the axis may still be moving. Use the machine&apos;s emergency stop.</source>
        <translation>%1 该驱动器没有看门狗：轴可能仍在运动。请使用机器的急停按钮。</translation>
    </message>
    <message>
        <source>The link to the drive was closed.</source>
        <translation>与驱动器的连接已关闭。</translation>
    </message>
</context>
<context>
    <name>dd::DriveConnection</name>
    <message>
        <source>The %1 family is not available in this build.</source>
        <translation>此版本不支持 %1 系列。</translation>
    </message>
</context>
<context>
    <name>dd::DriveDeskMain</name>
    <message>
        <source>DriveDesk: commissioning workbench for servo and stepper drives.</source>
        <translation>DriveDesk：伺服和步进驱动器调试工具。</translation>
    </message>
    <message>
        <source>Start the simulated bench (one drive of each family) and connect to it.</source>
        <translation>启动模拟试验台（每个系列一台驱动器）并连接。</translation>
    </message>
    <message>
        <source>User-interface language for this session: en, zh_CN or system (default: the Language menu&apos;s choice).</source>
        <translation>本次运行的界面语言：en、zh_CN 或 system（默认：“语言”菜单中的选择）。</translation>
    </message>
    <message>
        <source>Connect at start-up and scan: a serial port (/dev/ttyUSB0, COM3), a CAN interface as plugin:interface (socketcan:can0), or &apos;last&apos; for the connection used last.</source>
        <translation>启动时连接并扫描：串口（/dev/ttyUSB0、COM3）、CAN 接口（插件:接口，如 socketcan:can0），或 last 表示上次使用的连接。</translation>
    </message>
    <message>
        <source>With --connect on a serial port: the baud rate (default: the family&apos;s).</source>
        <translation>与 --connect 串口配合：波特率（默认：系列默认值）。</translation>
    </message>
    <message>
        <source>With --connect on CAN: the bitrate in bit/s (default: the family&apos;s).</source>
        <translation>与 --connect CAN 配合：波特率，单位 bit/s（默认：系列默认值）。</translation>
    </message>
    <message>
        <source>With --family shuoke: rtu, ascii, plc or can.</source>
        <translation>与 --family shuoke 配合：rtu、ascii、plc 或 can。</translation>
    </message>
    <message>
        <source>Save a picture of the main window to this PNG file after the delay, then quit (documentation).</source>
        <translation>延时后将主窗口截图保存为此 PNG 文件，然后退出（用于文档）。</translation>
    </message>
    <message>
        <source>Seconds to wait before --screenshot (default 3).</source>
        <translation>--screenshot 之前等待的秒数（默认 3）。</translation>
    </message>
    <message>
        <source>The tab to show for the selected drive: overview, trend, ...</source>
        <translation>所选驱动器首先显示的标签页：overview、trend 等。</translation>
    </message>
    <message>
        <source>Select the first drive of this family that is found: %1.</source>
        <translation>选中找到的第一台该系列驱动器：%1。</translation>
    </message>
    <message>
        <source>Unknown family &apos;%1&apos; for --drive: use %2.</source>
        <translation>--drive 的驱动器系列“%1”未知：请用 %2。</translation>
    </message>
    <message>
        <source>With --connect: %1 or detect (default).</source>
        <translation>与 --connect 配合：%1 或 detect（默认，自动识别）。</translation>
    </message>
    <message>
        <source>A backup or run file: it is added to File &gt; Recent files and opens in the drive&apos;s tabs when a drive is selected.</source>
        <translation>备份文件或整定记录文件：加入“文件 &gt; 最近的文件”，选中驱动器后在该驱动器的标签页中打开。</translation>
    </message>
    <message>
        <source>Give one file at most (%1 given).</source>
        <translation>最多只能给一个文件（给了 %1 个）。</translation>
    </message>
</context>
<context>
    <name>dd::DriveHub</name>
    <message>
        <source>The connection is closed.</source>
        <translation>连接已关闭。</translation>
    </message>
    <message>
        <source>There is no drive at address %1.</source>
        <translation>地址 %1 上没有驱动器。</translation>
    </message>
    <message>
        <source>The operation was not started.</source>
        <translation>操作未能启动。</translation>
    </message>
</context>
<context>
    <name>dd::DriveWorkspace</name>
    <message>
        <source>Select a drive in the bus tree.

No drive yet? Use File → Connect… to open a serial port or a CAN interface and scan it, or File → Demo bench to try DriveDesk with simulated drives.</source>
        <translation>请在总线树中选择一台驱动器。

还没有驱动器？使用“文件 → 连接…”打开串口或 CAN 接口并扫描，或使用“文件 → 演示试验台”以模拟驱动器试用 DriveDesk。</translation>
    </message>
</context>
<context>
    <name>dd::EtaEstimator</name>
    <message numerus="yes">
        <source>about %n s</source>
        <translation>
            <numerusform>约 %n 秒</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>about %n min</source>
        <translation>
            <numerusform>约 %n 分钟</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>dd::FrameDescriber</name>
    <message>
        <source>alarm %1</source>
        <translation>报警 %1</translation>
    </message>
    <message>
        <source>no alarm</source>
        <translation>无报警</translation>
    </message>
    <message>
        <source>keep-alive</source>
        <translation>保活</translation>
    </message>
    <message>
        <source>heartbeat: idle, position %1</source>
        <translation>心跳：停止，位置 %1</translation>
    </message>
    <message>
        <source>heartbeat: running, position %1</source>
        <translation>心跳：运行中，位置 %1</translation>
    </message>
    <message>
        <source>read P%1</source>
        <translation>读 P%1</translation>
    </message>
    <message>
        <source>P%1 = %2</source>
        <translation>P%1 = %2</translation>
    </message>
    <message>
        <source>read %1</source>
        <translation>读 %1</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>write P%1 = %2</source>
        <translation>写 P%1 = %2</translation>
    </message>
    <message>
        <source>run at %1 r/min</source>
        <translation>以 %1 r/min 运行</translation>
    </message>
    <message>
        <source>run at 0 r/min (halt)</source>
        <translation>以 0 r/min 运行（停住）</translation>
    </message>
    <message>
        <source>move by %1</source>
        <translation>相对移动 %1</translation>
    </message>
    <message>
        <source>move to %1</source>
        <translation>移动到 %1</translation>
    </message>
    <message>
        <source>positioning speed %1 r/min</source>
        <translation>定位速度 %1 r/min</translation>
    </message>
    <message>
        <source>servo on</source>
        <translation>伺服使能</translation>
    </message>
    <message>
        <source>servo off</source>
        <translation>伺服关闭</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>stop and disable</source>
        <translation>停止并取消使能</translation>
    </message>
    <message>
        <source>set position to %1</source>
        <translation>设置位置为 %1</translation>
    </message>
    <message>
        <source>clear alarm</source>
        <translation>清除报警</translation>
    </message>
    <message>
        <source>EE operation %1</source>
        <translation>EE 操作 %1</translation>
    </message>
    <message>
        <source>write %1 = %2</source>
        <translation>写 %1 = %2</translation>
    </message>
    <message>
        <source>all (broadcast): %1</source>
        <translation>全部（广播）：%1</translation>
    </message>
    <message>
        <source>exception %1: %2</source>
        <translation>异常 %1：%2</translation>
    </message>
    <message>
        <source>… (%1 values)</source>
        <translation>…（共 %1 个值）</translation>
    </message>
    <message>
        <source>EE operation running</source>
        <translation>EE 操作进行中</translation>
    </message>
    <message>
        <source>EE operation %1 done</source>
        <translation>EE 操作 %1 完成</translation>
    </message>
    <message>
        <source>written %1 = %2</source>
        <translation>已写 %1 = %2</translation>
    </message>
    <message>
        <source>EE operation accepted</source>
        <translation>EE 操作已接受</translation>
    </message>
    <message>
        <source>written %1</source>
        <translation>已写 %1</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <source>%1: OK</source>
        <translation>%1：成功</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>left limit</source>
        <translation>左限位</translation>
    </message>
    <message>
        <source>origin</source>
        <translation>原点</translation>
    </message>
    <message>
        <source>right limit</source>
        <translation>右限位</translation>
    </message>
    <message>
        <source>enable input</source>
        <translation>使能输入</translation>
    </message>
    <message>
        <source>inputs %1</source>
        <translation>输入 %1</translation>
    </message>
    <message>
        <source>positive first</source>
        <translation>先正向</translation>
    </message>
    <message>
        <source>negative first</source>
        <translation>先负向</translation>
    </message>
    <message>
        <source>code %1 (%2 baud)</source>
        <translation>代码 %1（%2 波特）</translation>
    </message>
    <message>
        <source>code %1 (%2 kbit/s)</source>
        <translation>代码 %1（%2 kbit/s）</translation>
    </message>
</context>
<context>
    <name>dd::FrameMonitorDock</name>
    <message>
        <source>Save frames</source>
        <translation>保存报文</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;Text files (*.txt *.log)</source>
        <translation>CSV 文件 (*.csv);;文本文件 (*.txt *.log)</translation>
    </message>
    <message>
        <source>%1 frames, %2 shown</source>
        <translation>共 %1 帧，显示 %2 帧</translation>
    </message>
    <message>
        <source>paused: %1 new frames wait</source>
        <translation>已暂停：%1 帧新报文待显示</translation>
    </message>
    <message>
        <source>%1 oldest frames dropped (the monitor keeps the last %2)</source>
        <translation>已丢弃最早的 %1 帧（监视器只保留最近 %2 帧）</translation>
    </message>
    <message>
        <source>Frame monitor</source>
        <translation>报文监视</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>暂停(&amp;P)</translation>
    </message>
    <message>
        <source>Hold the view still. Frames are still recorded and appear when you resume.</source>
        <translation>冻结显示。报文仍在记录，继续后显示。</translation>
    </message>
    <message>
        <source>C&amp;lear</source>
        <translation>清空(&amp;L)</translation>
    </message>
    <message>
        <source>Forget every recorded frame</source>
        <translation>清除所有已记录的报文</translation>
    </message>
    <message>
        <source>&amp;Save…</source>
        <translation>保存(&amp;S)…</translation>
    </message>
    <message>
        <source>Save the frames shown (with the filter applied) as CSV or text</source>
        <translation>将当前显示（已过滤）的报文保存为 CSV 或文本</translation>
    </message>
    <message>
        <source>Filter: hex bytes, meaning, link…</source>
        <translation>过滤：十六进制字节、含义、链路…</translation>
    </message>
    <message>
        <source>All directions</source>
        <translation>所有方向</translation>
    </message>
    <message>
        <source>TX and RX</source>
        <translation>发送和接收</translation>
    </message>
    <message>
        <source>TX only</source>
        <translation>仅发送</translation>
    </message>
    <message>
        <source>RX only</source>
        <translation>仅接收</translation>
    </message>
    <message>
        <source>Discarded only</source>
        <translation>仅丢弃</translation>
    </message>
    <message>
        <source>TX: sent by DriveDesk; RX: received; discarded: bytes that were not a valid reply</source>
        <translation>TX：DriveDesk 发送；RX：接收；丢弃：不是有效应答的字节</translation>
    </message>
    <message>
        <source>All links</source>
        <translation>所有链路</translation>
    </message>
    <message>
        <source>&amp;Follow</source>
        <translation>跟随(&amp;F)</translation>
    </message>
    <message>
        <source>Keep the newest frame in view</source>
        <translation>始终显示最新报文</translation>
    </message>
</context>
<context>
    <name>dd::FrameMonitorModel</name>
    <message>
        <source>discarded</source>
        <translation>已丢弃</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>链路</translation>
    </message>
    <message>
        <source>Dir.</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Frame (hex)</source>
        <translation>报文（十六进制）</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含义</translation>
    </message>
</context>
<context>
    <name>dd::JsonFieldReader</name>
    <message>
        <source>%1: field &quot;%2&quot;</source>
        <translation>%1：字段“%2”</translation>
    </message>
    <message>
        <source>must be an integer (found %1)</source>
        <translation>必须是整数（实际为 %1）</translation>
    </message>
    <message>
        <source>holds a number too large to be exact (the limit is ±%1)</source>
        <translation>数值过大，无法精确表示（上限为 ±%1）</translation>
    </message>
    <message>
        <source>must be a whole number (found %1)</source>
        <translation>必须是整数（实际为 %1）</translation>
    </message>
    <message>
        <source>%1: required field &quot;%2&quot; is missing</source>
        <translation>%1：缺少必需字段“%2”</translation>
    </message>
    <message>
        <source>%1 = %2 is outside the allowed range %3 to %4</source>
        <translation>%1 = %2 超出允许范围 %3 到 %4</translation>
    </message>
    <message>
        <source>must be a number (found %1)</source>
        <translation>必须是数值（实际为 %1）</translation>
    </message>
    <message>
        <source>must be a string (found %1)</source>
        <translation>必须是字符串（实际为 %1）</translation>
    </message>
    <message>
        <source>is longer than %1 characters</source>
        <translation>超过 %1 个字符</translation>
    </message>
    <message>
        <source>must not be empty</source>
        <translation>不能为空</translation>
    </message>
    <message>
        <source>must be true or false (found %1)</source>
        <translation>必须是 true 或 false（实际为 %1）</translation>
    </message>
    <message>
        <source>must be an object (found %1)</source>
        <translation>必须是对象（实际为 %1）</translation>
    </message>
    <message>
        <source>must be an array (found %1)</source>
        <translation>必须是数组（实际为 %1）</translation>
    </message>
    <message>
        <source>has more than %1 entries</source>
        <translation>超过 %1 项</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a language code (use e.g. &quot;en&quot;, &quot;zh&quot;, &quot;zh_CN&quot;)</source>
        <translation>%1：“%2”不是语言代码（例如“en”、“zh”、“zh_CN”）</translation>
    </message>
    <message>
        <source>%1 needs a non-empty &quot;%2&quot; text</source>
        <translation>%1 需要非空的“%2”文本</translation>
    </message>
    <message>
        <source>%1: unknown field &quot;%2&quot;</source>
        <translation>%1：未知字段“%2”</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 bytes; it is not a file DriveDesk wrote</source>
        <translation>%1 大于 %2 字节，不是 DriveDesk 生成的文件</translation>
    </message>
    <message>
        <source> (is the file empty or truncated?)</source>
        <translation>（文件是否为空或不完整？）</translation>
    </message>
    <message>
        <source>%1 is not valid JSON: %2 at byte %3%4</source>
        <translation>%1 不是有效的 JSON：第 %3 字节处%2%4</translation>
    </message>
    <message>
        <source>%1: the top level must be a JSON object</source>
        <translation>%1：顶层必须是 JSON 对象</translation>
    </message>
</context>
<context>
    <name>dd::MainWindow</name>
    <message>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <source>Demo bench</source>
        <translation>演示试验台</translation>
    </message>
    <message>
        <source>Select a drive first: %1 is opened in one of its tabs.</source>
        <translation>请先选择驱动器：%1 将在该驱动器的某个标签页中打开。</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;Recent files</source>
        <translation>最近的文件(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation>连接(&amp;C)…</translation>
    </message>
    <message>
        <source>Open a serial port or a CAN interface and scan it for drives (%1)</source>
        <translation>打开串口或 CAN 接口并扫描驱动器（%1）</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>断开连接(&amp;D)</translation>
    </message>
    <message>
        <source>Close the selected connection</source>
        <translation>关闭所选连接</translation>
    </message>
    <message>
        <source>Disconnect &amp;all</source>
        <translation>全部断开(&amp;A)</translation>
    </message>
    <message>
        <source>De&amp;mo bench</source>
        <translation>演示试验台(&amp;M)</translation>
    </message>
    <message>
        <source>Start simulated drives of every family and connect to them</source>
        <translation>启动各系列的模拟驱动器并连接</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;About DriveDesk</source>
        <translation>关于 DriveDesk(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>关于 Qt(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;System language</source>
        <translation>跟随系统(&amp;S)</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>总线</translation>
    </message>
    <message>
        <source>&amp;Bus tree</source>
        <translation>总线树(&amp;B)</translation>
    </message>
    <message>
        <source>Main tool bar</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>Commissioning workbench</source>
        <translation>调试工作台</translation>
    </message>
    <message>
        <source>%1 is moving</source>
        <translation>%1 正在运动</translation>
    </message>
    <message>
        <source>%1 has its power stage on</source>
        <translation>%1 的功率级已开启</translation>
    </message>
    <message>
        <source>Quit DriveDesk?</source>
        <translation>退出 DriveDesk？</translation>
    </message>
    <message>
        <source>%1.

Quitting ends DriveDesk&apos;s control of these drives. STOP them all (as the STOP button does) and quit?</source>
        <translation>%1。

退出后 DriveDesk 将不再控制这些驱动器。要全部停止（与“停止”按钮相同）并退出吗？</translation>
    </message>
    <message>
        <source>; </source>
        <translation>；</translation>
    </message>
    <message>
        <source>STOP and quit</source>
        <translation>停止并退出</translation>
    </message>
    <message>
        <source>STOP report…</source>
        <translation>停止报告…</translation>
    </message>
</context>
<context>
    <name>dd::ModbusLink</name>
    <message>
        <source>The Modbus link was destroyed.</source>
        <translation>Modbus 连接已被销毁。</translation>
    </message>
    <message>
        <source>The serial port is not open.</source>
        <translation>串口未打开。</translation>
    </message>
    <message>
        <source>Invalid Modbus request (function %1, address %2, %3 registers): nothing was sent.</source>
        <translation>无效的 Modbus 请求（功能码 %1，地址 %2，%3 个寄存器）：未发送任何数据。</translation>
    </message>
    <message>
        <source>The drive at address %1 rejected the request (Modbus exception %2: %3).</source>
        <translation>地址 %1 的驱动器拒绝了请求（Modbus 异常 %2：%3）。</translation>
    </message>
    <message>
        <source>The reply from address %1 on %2 does not fit the request (%3).</source>
        <translation>%2 上地址 %1 的应答与请求不符（%3）。</translation>
    </message>
    <message>
        <source>The drive at address %1 rejected the request (Modbus exception %2: %3; the reply carried address byte %4).</source>
        <translation>地址 %1 的驱动器拒绝了请求（Modbus 异常 %2：%3；应答中的地址字节为 %4）。</translation>
    </message>
</context>
<context>
    <name>dd::MotionPanel</name>
    <message>
        <source>Jog ended: the drive stopped answering.</source>
        <translation>点动已结束：驱动器不再应答。</translation>
    </message>
    <message>
        <source>Enable</source>
        <translation>使能</translation>
    </message>
    <message>
        <source>Disable</source>
        <translation>取消使能</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>回零</translation>
    </message>
    <message>
        <source>Set position</source>
        <translation>设置位置</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>运动</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>%1: done.</source>
        <translation>%1：完成。</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 失败：%2</translation>
    </message>
    <message>
        <source>Move to %1</source>
        <translation>移动到 %1</translation>
    </message>
    <message>
        <source>Move by %1</source>
        <translation>相对移动 %1</translation>
    </message>
    <message>
        <source>Jogging at %1 %2 — let go to stop.</source>
        <translation>正在以 %1 %2 点动 — 松开即停止。</translation>
    </message>
    <message>
        <source>Jog stopped: the button was released.</source>
        <translation>点动已停止：按钮已松开。</translation>
    </message>
    <message>
        <source>Jog stopped: the pointer left the button.</source>
        <translation>点动已停止：鼠标离开了按钮。</translation>
    </message>
    <message>
        <source>Jog stopped: the button lost the keyboard focus.</source>
        <translation>点动已停止：按钮失去了键盘焦点。</translation>
    </message>
    <message>
        <source>Jog stopped: the window was deactivated.</source>
        <translation>点动已停止：窗口不再处于活动状态。</translation>
    </message>
    <message>
        <source>Jog stopped: DriveDesk is no longer the active application.</source>
        <translation>点动已停止：DriveDesk 不再是活动应用程序。</translation>
    </message>
    <message>
        <source>Jog stopped: the Motion tab was hidden.</source>
        <translation>点动已停止：“运动”页已隐藏。</translation>
    </message>
    <message>
        <source>Jog stopped: jogging was disabled.</source>
        <translation>点动已停止：点动已被禁用。</translation>
    </message>
    <message>
        <source>Jog stopped: the connection was lost.</source>
        <translation>点动已停止：连接已断开。</translation>
    </message>
    <message>
        <source>Jog stopped by the drive link: DriveDesk did not confirm the held button in time.</source>
        <translation>点动已由通讯链路停止：DriveDesk 未能及时确认按钮仍被按住。</translation>
    </message>
    <message>
        <source>Jog stopped: the drive did not start.</source>
        <translation>点动已停止：驱动器未启动。</translation>
    </message>
    <message>
        <source>Jog stopped.</source>
        <translation>点动已停止。</translation>
    </message>
    <message>
        <source>The jog of %1 was stopped because its hold was not renewed in time (the window was busy or frozen). Press the jog button again to continue.</source>
        <translation>%1 的点动已停止，因为按住状态未能及时续期（窗口忙碌或无响应）。请重新按下点动按钮继续。</translation>
    </message>
    <message>
        <source>%1 is not available on this drive.</source>
        <translation>此驱动器不支持“%1”。</translation>
    </message>
    <message>
        <source>Waiting for the drive&apos;s description…</source>
        <translation>正在等待驱动器信息…</translation>
    </message>
    <message>
        <source>State: %1</source>
        <translation>状态：%1</translation>
    </message>
    <message>
        <source>Position: %1 %2</source>
        <translation>位置：%1 %2</translation>
    </message>
    <message>
        <source>Power stage</source>
        <translation>使能</translation>
    </message>
    <message>
        <source>&amp;Enable</source>
        <translation>使能(&amp;E)</translation>
    </message>
    <message>
        <source>Switch the power stage on: the motor holds its position.</source>
        <translation>打开功率级：电机保持当前位置。</translation>
    </message>
    <message>
        <source>&amp;Disable</source>
        <translation>取消使能(&amp;D)</translation>
    </message>
    <message>
        <source>Switch the power stage off: the shaft turns freely.</source>
        <translation>关闭功率级：电机轴可自由转动。</translation>
    </message>
    <message>
        <source>Jog (hold to run)</source>
        <translation>点动（按住运行）</translation>
    </message>
    <message>
        <source>Jog &amp;speed:</source>
        <translation>点动速度(&amp;S)：</translation>
    </message>
    <message>
        <source>◀ Jog −</source>
        <translation>◀ 负向点动</translation>
    </message>
    <message>
        <source>Jog + ▶</source>
        <translation>正向点动 ▶</translation>
    </message>
    <message>
        <source>Hold a jog button (or focus it and hold Space): the axis turns only while it is held and stops when you let go, when the window loses the focus or when the connection drops.</source>
        <translation>按住点动按钮（或选中后按住空格键）：只有按住时轴才转动；松开、窗口失去焦点或连接断开时立即停止。</translation>
    </message>
    <message>
        <source>Not jogging.</source>
        <translation>未在点动。</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>定位运动</translation>
    </message>
    <message>
        <source>&amp;Relative by</source>
        <translation>相对移动(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Absolute to</source>
        <translation>绝对移动到(&amp;A)</translation>
    </message>
    <message>
        <source>Positioning speed:</source>
        <translation>定位速度：</translation>
    </message>
    <message>
        <source>&amp;Move</source>
        <translation>运动(&amp;M)</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>回零</translation>
    </message>
    <message>
        <source>Search positive direction first</source>
        <translation>先向正方向搜索</translation>
    </message>
    <message>
        <source>Search negative direction first</source>
        <translation>先向负方向搜索</translation>
    </message>
    <message>
        <source>&amp;Home</source>
        <translation>回零(&amp;H)</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Set the current position to:</source>
        <translation>将当前位置设为：</translation>
    </message>
    <message>
        <source>Se&amp;t</source>
        <translation>设置(&amp;T)</translation>
    </message>
    <message>
        <source>Stop this drive</source>
        <translation>停止此驱动器</translation>
    </message>
    <message>
        <source>STOP in the tool bar (Esc or F12) stops every drive on every connection.</source>
        <translation>工具栏上的“停止”（Esc 或 F12）会停止所有连接上的所有驱动器。</translation>
    </message>
    <message>
        <source>%1: sending…</source>
        <translation>%1：正在发送…</translation>
    </message>
    <message>
        <source>%1: started.</source>
        <translation>%1：已开始。</translation>
    </message>
    <message>
        <source>%1: started; its state cannot be read: %2</source>
        <translation>%1：已开始；无法读取其状态：%2</translation>
    </message>
    <message>
        <source>%1: stopped by alarm %2 at %3 %4.</source>
        <translation>%1：因报警 %2 停在 %3 %4。</translation>
    </message>
    <message>
        <source>%1: moving… position %2 %3</source>
        <translation>%1：运动中… 位置 %2 %3</translation>
    </message>
    <message>
        <source>%1 refused: %2</source>
        <translation>%1 被拒绝：%2</translation>
    </message>
    <message>
        <source>ended</source>
        <translation>已结束</translation>
    </message>
    <message>
        <source>stopped by STOP</source>
        <translation>被“停止”停下</translation>
    </message>
    <message>
        <source>stopped by “Stop this drive”</source>
        <translation>被“停止此驱动器”停下</translation>
    </message>
    <message>
        <source> Something outside this command stopped it: another master, the drive&apos;s own inputs or panel, or a limit.</source>
        <translation>是本命令之外的原因使其停止：另一个主站、驱动器自身的输入或面板，或限位。</translation>
    </message>
    <message>
        <source>%1: %2; the drive does not report where the axis is.</source>
        <translation>%1：%2；驱动器未报告轴的位置。</translation>
    </message>
    <message>
        <source>%1: done, the axis is at rest at its target, %2 %3.</source>
        <translation>%1：完成，轴已静止在目标位置 %2 %3。</translation>
    </message>
    <message>
        <source>%1: done, the origin was found; the axis is at rest at %2 %3.</source>
        <translation>%1：完成，已找到原点；轴静止在 %2 %3。</translation>
    </message>
    <message>
        <source>%1: %2 at %3 %4, %5 %4 short of the target (%6 %4).%7</source>
        <translation>%1：%2，位于 %3 %4，距目标（%6 %4）还差 %5 %4。%7</translation>
    </message>
    <message>
        <source>%1: %2 at %3 %4, %5 %4 beyond the target (%6 %4).%7</source>
        <translation>%1：%2，位于 %3 %4，超过目标（%6 %4）%5 %4。%7</translation>
    </message>
    <message>
        <source>%1: %2 at %3 %4; the origin was not found.</source>
        <translation>%1：%2，位于 %3 %4；未找到原点。</translation>
    </message>
    <message>
        <source>the power stage is off. DriveDesk does not switch it on by itself: press Enable first.</source>
        <translation>功率级已关闭。DriveDesk 不会自行开启：请先按“使能”。</translation>
    </message>
    <message>
        <source>The power stage is off: jog, move and homing are refused until you switch it on (DriveDesk does not do it by itself).</source>
        <translation>功率级已关闭：在您开启之前，点动、定位和回原点均被拒绝（DriveDesk 不会自行开启）。</translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation>已拒绝：%1</translation>
    </message>
    <message>
        <source>Enable: done earlier; the power stage is off now (STOP, a disable or the drive).</source>
        <translation>使能：此前已完成；功率级现已关闭（停止、禁用或驱动器自身）。</translation>
    </message>
    <message>
        <source>Disable: done earlier; the power stage is on again.</source>
        <translation>禁用：此前已完成；功率级现已重新开启。</translation>
    </message>
    <message>
        <source>%1: reading where the axis is…</source>
        <translation>%1：正在读取轴的位置…</translation>
    </message>
    <message>
        <source>The drive does not report its position.</source>
        <translation>驱动器未报告其位置。</translation>
    </message>
    <message>
        <source>%1 failed: where the axis is could not be read, nothing was sent: %2</source>
        <translation>%1 失败：无法读取轴的位置，未发送任何命令：%2</translation>
    </message>
</context>
<context>
    <name>dd::OverviewPanel</name>
    <message>
        <source>Overview</source>
        <translation>概览</translation>
    </message>
    <message>
        <source>Identity</source>
        <translation>设备信息</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Capabilities</source>
        <translation>支持的功能</translation>
    </message>
    <message>
        <source>Family:</source>
        <translation>系列：</translation>
    </message>
    <message>
        <source>Address:</source>
        <translation>地址：</translation>
    </message>
    <message>
        <source>Model:</source>
        <translation>型号：</translation>
    </message>
    <message>
        <source>Firmware:</source>
        <translation>固件：</translation>
    </message>
    <message>
        <source>Link:</source>
        <translation>通讯链路：</translation>
    </message>
    <message>
        <source>Communication:</source>
        <translation>通讯：</translation>
    </message>
    <message>
        <source>Motion:</source>
        <translation>运动：</translation>
    </message>
    <message>
        <source>Power stage:</source>
        <translation>使能：</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>位置：</translation>
    </message>
    <message>
        <source>Alarm:</source>
        <translation>报警：</translation>
    </message>
    <message>
        <source>Last update:</source>
        <translation>最后更新：</translation>
    </message>
    <message>
        <source>Function</source>
        <translation>功能</translation>
    </message>
    <message>
        <source>Available</source>
        <translation>可用</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <source>Read the identity and the status of the drive again</source>
        <translation>重新读取驱动器的设备信息和状态</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>No</source>
        <translation>否</translation>
    </message>
    <message>
        <source>Online</source>
        <translation>在线</translation>
    </message>
    <message>
        <source>No answer</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>Not polled yet</source>
        <translation>尚未查询</translation>
    </message>
    <message>
        <source>No (%1)</source>
        <translation>否（%1）</translation>
    </message>
</context>
<context>
    <name>dd::ParameterDictionary</name>
    <message>
        <source>%1 must be an object (found %2)</source>
        <translation>%1 必须是对象（实际为 %2）</translation>
    </message>
    <message>
        <source>%1: key &quot;%2&quot; must start with a letter and hold only letters, digits, &apos;_&apos;, &apos;.&apos; and &apos;-&apos;</source>
        <translation>%1：键名“%2”必须以字母开头，且只能包含字母、数字、“_”、“.”和“-”</translation>
    </message>
    <message>
        <source>%1: key &quot;%2&quot; names parameter %3 but the index is %4</source>
        <translation>%1：键名“%2”对应参数 %3，但序号为 %4</translation>
    </message>
    <message>
        <source>%1: field &quot;type&quot; = &quot;%2&quot; is not one of uint8, int16, uint16, int32, uint32</source>
        <translation>%1：字段“type” = “%2”不是 uint8、int16、uint16、int32、uint32 之一</translation>
    </message>
    <message>
        <source>%1: field &quot;access&quot; = &quot;%2&quot; is not one of rw, ro, wo</source>
        <translation>%1：字段“access” = “%2”不是 rw、ro、wo 之一</translation>
    </message>
    <message>
        <source>%1: min %2 is greater than max %3</source>
        <translation>%1：最小值 %2 大于最大值 %3</translation>
    </message>
    <message>
        <source>%1: the range %2 to %3 does not fit the type %4 (%5 to %6)</source>
        <translation>%1：范围 %2 到 %3 超出类型 %4 的取值范围（%5 到 %6）</translation>
    </message>
    <message>
        <source>%1: default %2 is outside the range %3 to %4</source>
        <translation>%1：默认值 %2 超出范围 %3 到 %4</translation>
    </message>
    <message>
        <source>%1: a write-only parameter cannot have a readCommand</source>
        <translation>%1：只写参数不能有 readCommand</translation>
    </message>
    <message>
        <source>%1: models[%2] must be a model name</source>
        <translation>%1：models[%2] 必须是型号名称</translation>
    </message>
    <message>
        <source>%1 is not a DriveDesk parameter dictionary (format &quot;%2&quot;, expected &quot;%3&quot;)</source>
        <translation>%1 不是 DriveDesk 参数字典（格式为“%2”，应为“%3”）</translation>
    </message>
    <message>
        <source>%1: dictionary format version %2 is not supported (this DriveDesk reads version %3)</source>
        <translation>%1：不支持参数字典格式版本 %2（本版 DriveDesk 读取版本 %3）</translation>
    </message>
    <message>
        <source>%1: unknown drive family &quot;%2&quot; (known: %3)</source>
        <translation>%1：未知的驱动器系列“%2”（已知：%3）</translation>
    </message>
    <message>
        <source>%1 is a dictionary for %2 drives, not for %3</source>
        <translation>%1 是 %2 驱动器的参数字典，不适用于 %3</translation>
    </message>
    <message>
        <source>%1: field &quot;valueType&quot; = &quot;%2&quot; is not one of uint8, int16, uint16, int32, uint32</source>
        <translation>%1：字段“valueType” = “%2”不是 uint8、int16、uint16、int32、uint32 之一</translation>
    </message>
    <message>
        <source>%1: the dictionary has no parameters</source>
        <translation>%1：参数字典中没有参数</translation>
    </message>
    <message>
        <source>%1: index %2 is already used by %3</source>
        <translation>%1：序号 %2 已被 %3 占用</translation>
    </message>
    <message>
        <source>%1: key &quot;%2&quot; is already used (keys are case-insensitive)</source>
        <translation>%1：键名“%2”已被使用（键名不区分大小写）</translation>
    </message>
    <message>
        <source>%1: register %2 is already used by %3</source>
        <translation>%1：寄存器 %2 已被 %3 占用</translation>
    </message>
    <message>
        <source>Unknown parameter &quot;%1&quot; for %2 drives: give a number (12), a key (%3) or a name</source>
        <translation>%2 驱动器没有参数“%1”：请输入序号（如 12）、键名（如 %3）或名称</translation>
    </message>
    <message>
        <source>There is no parameter %1 for %2 drives</source>
        <translation>%2 驱动器没有参数 %1</translation>
    </message>
    <message>
        <source>%1: %2 is outside the allowed range %3 to %4</source>
        <translation>%1：%2 超出允许范围 %3 到 %4</translation>
    </message>
    <message>
        <source>%1: %2 %5 is outside the allowed range %3 to %4 %5</source>
        <translation>%1：%2 %5 超出允许范围 %3 到 %4 %5</translation>
    </message>
    <message>
        <source>%1 is read-only: the drive does not accept a new value</source>
        <translation>%1 为只读参数：驱动器不接受新值</translation>
    </message>
    <message>
        <source>%1: a readable %2 parameter needs a readCommand</source>
        <translation>%1：可读的 %2 参数需要 readCommand</translation>
    </message>
    <message>
        <source>%1: a %2 parameter needs a register</source>
        <translation>%1：%2 参数需要寄存器地址</translation>
    </message>
    <message>
        <source>%1 must be an object with &quot;key&quot; and &quot;role&quot;</source>
        <translation>%1 必须是包含 &quot;key&quot; 和 &quot;role&quot; 的对象</translation>
    </message>
    <message>
        <source>%1: no parameter has the key &quot;%2&quot;</source>
        <translation>%1：没有键名为“%2”的参数</translation>
    </message>
    <message>
        <source>%1: %2 is write-only; a tuning parameter must be readable</source>
        <translation>%1：%2 为只写参数；整定参数必须可读</translation>
    </message>
    <message>
        <source>%1: unknown role &quot;%2&quot; (known: %3)</source>
        <translation>%1：未知的用途“%2”（已知：%3）</translation>
    </message>
    <message>
        <source>%1: role &quot;%2&quot; is already given to tuning[%3]</source>
        <translation>%1：用途“%2”已分配给 tuning[%3]</translation>
    </message>
    <message>
        <source>%1: %2 is already in tuning[%3]</source>
        <translation>%1：%2 已在 tuning[%3] 中</translation>
    </message>
</context>
<context>
    <name>dd::ParameterDiff</name>
    <message>
        <source>Parameter %1 has no value in the backup file, so it cannot be restored</source>
        <translation>参数 %1 在备份文件中没有数值，无法恢复</translation>
    </message>
    <message>
        <source>Parameter %1 is read-only, so it cannot be restored</source>
        <translation>参数 %1 为只读，无法恢复</translation>
    </message>
</context>
<context>
    <name>dd::ParameterTransfer</name>
    <message>
        <source>A backup or restore is already running on this drive.</source>
        <translation>该驱动器上已有备份或恢复正在进行。</translation>
    </message>
    <message>
        <source>The drive is gone.</source>
        <translation>驱动器已不在。</translation>
    </message>
    <message>
        <source>The drive could not be identified: %1</source>
        <translation>无法识别驱动器：%1</translation>
    </message>
    <message>
        <source>The parameter dictionary lists no readable parameter.</source>
        <translation>参数字典中没有可读的参数。</translation>
    </message>
    <message>
        <source>Not every parameter was restored: %1.</source>
        <translation>并非所有参数都已恢复：%1。</translation>
    </message>
</context>
<context>
    <name>dd::RecentFiles</name>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>&amp;Clear list</source>
        <translation>清除列表(&amp;C)</translation>
    </message>
</context>
<context>
    <name>dd::ScanProgressWidget</name>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) found</source>
        <translation>
            <numerusform>已找到 %n 台驱动器</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 left · %2</source>
        <translation>剩余%1 · %2</translation>
    </message>
</context>
<context>
    <name>dd::SerialLink</name>
    <message>
        <source>The serial link was destroyed.</source>
        <translation>串口连接已被销毁。</translation>
    </message>
    <message>
        <source>Cannot open serial port %1: %2. Check the device name, that no other program is using it, and that you may access it (dialout group).</source>
        <translation>无法打开串口 %1：%2。请检查设备名称、是否被其他程序占用，以及是否有访问权限（dialout 组）。</translation>
    </message>
    <message>
        <source>The serial port %1 was closed.</source>
        <translation>串口 %1 已关闭。</translation>
    </message>
    <message>
        <source>The serial port is not open.</source>
        <translation>串口未打开。</translation>
    </message>
    <message>
        <source>The drive&apos;s reply on %1 failed its checksum. Check the cable shielding, the bus termination and the baud rate.</source>
        <translation>%1 上驱动器应答的校验失败。请检查电缆屏蔽、总线终端电阻和波特率。</translation>
    </message>
    <message>
        <source>No reply on %1 within %2 ms. Check the drive address, the baud rate, the wiring (A/B swapped?) and the bus termination.</source>
        <translation>%1 上 %2 ms 内无应答。请检查驱动器地址、波特率、接线（A/B 是否接反？）和总线终端电阻。</translation>
    </message>
    <message>
        <source>The serial port %1 failed (%2). Was the adapter unplugged?</source>
        <translation>串口 %1 出错（%2）。适配器是否已拔出？</translation>
    </message>
    <message>
        <source>Answers came after the timeout: the drive is slower than the response allowance (%1 ms): raise the timeout.</source>
        <translation>应答在超时之后才到达：驱动器比应答余量（%1 ms）慢，请增大超时时间。</translation>
    </message>
    <message>
        <source>No reply on %1 within %2 ms but a frame of the awaited shape that came %3 us after the request, sooner than the wire can carry request and reply (%4 us), while an earlier request was still unanswered: it was dropped as that request&apos;s late answer. The next attempt accepts a fast reply; if this one was the last, raise the retries (--retries).</source>
        <translation>%1 上在 %2 毫秒内没有应答，只收到一个符合预期格式的帧：它在请求发出后 %3 微秒即到达，早于线路传送请求和应答所需的时间（%4 微秒），而先前的一个请求尚未得到应答，因此它被视为该请求的迟到应答而丢弃。下一次尝试会接受快速应答；如果这已是最后一次尝试，请增加重试次数（--retries）。</translation>
    </message>
    <message>
        <source>The line was never quiet: bytes that answered nothing kept coming, and the request was sent into them. Is another master on the bus, or a drive sending on its own? Stop the other sender; a longer timeout will not help.</source>
        <translation>总线始终不空闲：不断有不属于任何应答的字节到来，请求只能在其间发出。总线上是否还有另一个主站，或有驱动器在自行发送？请停止另一个发送方；加长超时没有用。</translation>
    </message>
</context>
<context>
    <name>dd::SerialPortWatcher</name>
    <message>
        <source>Virtual port (pseudo-terminal)</source>
        <translation>虚拟端口（伪终端）</translation>
    </message>
</context>
<context>
    <name>dd::ServoCanBackend</name>
    <message>
        <source>&quot;%1&quot; is not a CAN interface: write plugin:interface, e.g. socketcan:can0 or virtualcan:can0.</source>
        <translation>“%1”不是 CAN 接口：请按“插件:接口”填写，例如 socketcan:can0 或 virtualcan:can0。</translation>
    </message>
    <message>
        <source>servo-can.emergencyStop must be &quot;disable&quot; or &quot;hold&quot;, not &quot;%1&quot;.</source>
        <translation>servo-can.emergencyStop 必须为“disable”或“hold”，而不是“%1”。</translation>
    </message>
    <message>
        <source>servo-can.maxInFlight must be at least 1.</source>
        <translation>servo-can.maxInFlight 至少为 1。</translation>
    </message>
    <message>
        <source>%1, %2 kbit/s</source>
        <translation>%1，%2 kbit/s</translation>
    </message>
</context>
<context>
    <name>dd::ServoCanDiscovery</name>
    <message>
        <source>The CAN link is not open.</source>
        <translation>CAN 连接未打开。</translation>
    </message>
    <message>
        <source>The CAN link was closed.</source>
        <translation>CAN 连接已关闭。</translation>
    </message>
    <message>
        <source>The scan was cancelled.</source>
        <translation>扫描已取消。</translation>
    </message>
    <message>
        <source>alarm %1</source>
        <translation>报警 %1</translation>
    </message>
    <message>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>停止</translation>
    </message>
</context>
<context>
    <name>dd::ServoCanDrive</name>
    <message>
        <source>The servo-can protocol has no homing command. Move to the reference point and use &quot;set position&quot; (0x50) instead.</source>
        <translation>servo-can 协议没有回零命令。请运动到参考点后使用“设置位置”（0x50）。</translation>
    </message>
    <message>
        <source>The servo-can protocol has no EEPROM command.</source>
        <translation>servo-can 协议没有 EEPROM 命令。</translation>
    </message>
    <message>
        <source>The CAN link to station %1 is not open.</source>
        <translation>到站号 %1 的 CAN 连接未打开。</translation>
    </message>
    <message>
        <source>Station %1 did not start within %2 ms. Is an alarm active? Is parameter 4 = 8 (internal run control) and parameter 74 = 1 (CAN)?</source>
        <translation>站号 %1 在 %2 ms 内未启动。是否有报警？参数 4 是否为 8（内部运行控制）、参数 74 是否为 1（CAN）？</translation>
    </message>
    <message>
        <source>No heartbeat from station %1. Is the drive powered, is parameter 74 = 1 (CAN mode) and is the station number right?</source>
        <translation>未收到站号 %1 的心跳。驱动器是否上电？参数 74 是否为 1（CAN 模式）？站号是否正确？</translation>
    </message>
    <message>
        <source>Parameter 75 (station) is %1 but the drive answers as station %2.</source>
        <translation>参数 75（站号）为 %1，但驱动器以站号 %2 应答。</translation>
    </message>
    <message>
        <source>Parameter 74 is %1: set it to 1 for CAN communication mode.</source>
        <translation>参数 74 为 %1：CAN 通讯模式需设为 1。</translation>
    </message>
    <message>
        <source>Parameter 4 is %1: set it to 8 (internal run control) to move the axis over CAN.</source>
        <translation>参数 4 为 %1：要通过 CAN 控制运动，需设为 8（内部运行控制）。</translation>
    </message>
    <message>
        <source>Status of station %1</source>
        <translation>站号 %1 的状态</translation>
    </message>
    <message>
        <source>Alarm of station %1</source>
        <translation>站号 %1 的报警</translation>
    </message>
    <message>
        <source>Station %1 still reports alarm %2 after the clear command. Remove the cause of the alarm first.</source>
        <translation>发送清除命令后，站号 %1 仍报警 %2。请先排除报警原因。</translation>
    </message>
    <message>
        <source>Parameter %1 does not exist: servo-can parameters are 0 to %2.</source>
        <translation>参数 %1 不存在：servo-can 参数为 0 到 %2。</translation>
    </message>
    <message>
        <source>Station %1, P%2: %3</source>
        <translation>站号 %1，P%2：%3</translation>
    </message>
    <message>
        <source>P%1 = %2 is out of range: servo-can parameters are 16-bit values from -32768 to 32767. Nothing was written.</source>
        <translation>P%1 = %2 超出范围：servo-can 参数为 -32768 到 32767 的 16 位数值。未写入任何数据。</translation>
    </message>
    <message>
        <source>A servo-can drive has no channel &quot;%1&quot;.</source>
        <translation>servo-can 驱动器没有通道“%1”。</translation>
    </message>
    <message>
        <source>Station %1, %2: %3</source>
        <translation>站号 %1，%2：%3</translation>
    </message>
    <message>
        <source>A move needs a positive positioning speed (r/min); %1 was given.</source>
        <translation>运动需要正的定位速度（r/min），给定值为 %1。</translation>
    </message>
    <message>
        <source>Target %1 does not fit the drive&apos;s 32-bit position.</source>
        <translation>目标位置 %1 超出驱动器 32 位位置的范围。</translation>
    </message>
    <message>
        <source>Position %1 does not fit the drive&apos;s 32-bit position.</source>
        <translation>位置 %1 超出驱动器 32 位位置的范围。</translation>
    </message>
    <message>
        <source>Station %1: position set to %2 but it reads back %3.</source>
        <translation>站号 %1：位置设为 %2，但回读为 %3。</translation>
    </message>
    <message>
        <source>Station %1 has sent no heartbeat for %2 ms either: has it lost power or its CAN cable?</source>
        <translation>站号 %1 也已 %2 ms 没有发送心跳：是否断电或 CAN 线缆脱落？</translation>
    </message>
    <message>
        <source>%1 reads of P%2 gave no value often enough to trust it.</source>
        <translation>读取 P%2 共 %1 次，没有一个值出现足够多次，无法确认。</translation>
    </message>
    <message>
        <source>The stop command was sent, but station %1 has sent no heartbeat since (%2 ms): it may not have received it.</source>
        <translation>停止命令已发送，但站号 %1 此后（%2 ms）没有发送心跳：它可能没有收到该命令。</translation>
    </message>
    <message>
        <source>A relative move of %1 pulses does not fit the drive&apos;s 32-bit command.</source>
        <translation>相对运动量 %1 超出驱动器 32 位指令的范围。</translation>
    </message>
</context>
<context>
    <name>dd::ServoModbusBackend</name>
    <message>
        <source>servo-modbus drives are reached over a serial port (RS485): give a port.</source>
        <translation>servo-modbus 驱动器通过串口（RS485）通讯：请指定端口。</translation>
    </message>
    <message>
        <source>%1 @ %2 baud, Modbus RTU (servo-modbus)</source>
        <translation>%1 @ %2 波特，Modbus RTU（servo-modbus）</translation>
    </message>
</context>
<context>
    <name>dd::ServoModbusDrive</name>
    <message>
        <source>Speed (DP-SPd)</source>
        <translation>速度（DP-SPd）</translation>
    </message>
    <message>
        <source>Position (DP-PoS)</source>
        <translation>位置（DP-PoS）</translation>
    </message>
    <message>
        <source>Position, low register (DP-PoS)</source>
        <translation>位置，低位寄存器（DP-PoS）</translation>
    </message>
    <message>
        <source>Position, high register (DP-PoS.)</source>
        <translation>位置，高位寄存器（DP-PoS.）</translation>
    </message>
    <message>
        <source>Command position (DP-CPo)</source>
        <translation>指令位置（DP-CPo）</translation>
    </message>
    <message>
        <source>Command position, low register (DP-CPo)</source>
        <translation>指令位置，低位寄存器（DP-CPo）</translation>
    </message>
    <message>
        <source>Command position, high register (DP-CPo.)</source>
        <translation>指令位置，高位寄存器（DP-CPo.）</translation>
    </message>
    <message>
        <source>Position error (DP-EPo)</source>
        <translation>位置偏差（DP-EPo）</translation>
    </message>
    <message>
        <source>Position error, low register (DP-EPo)</source>
        <translation>位置偏差，低位寄存器（DP-EPo）</translation>
    </message>
    <message>
        <source>Position error, high register (DP-EPo.)</source>
        <translation>位置偏差，高位寄存器（DP-EPo.）</translation>
    </message>
    <message>
        <source>Torque (DP-trq)</source>
        <translation>转矩（DP-trq）</translation>
    </message>
    <message>
        <source>Current (DP-I)</source>
        <translation>电流（DP-I）</translation>
    </message>
    <message>
        <source>Pulse frequency (DP-Frq)</source>
        <translation>脉冲频率（DP-Frq）</translation>
    </message>
    <message>
        <source>Speed command (DP-CS)</source>
        <translation>速度指令（DP-CS）</translation>
    </message>
    <message>
        <source>Torque command (DP-Ct)</source>
        <translation>转矩指令（DP-Ct）</translation>
    </message>
    <message>
        <source>Rotor absolute position (DP-APo)</source>
        <translation>转子绝对位置（DP-APo）</translation>
    </message>
    <message>
        <source>Input terminals (DP-In)</source>
        <translation>输入端子（DP-In）</translation>
    </message>
    <message>
        <source>Output terminals (DP-oUt)</source>
        <translation>输出端子（DP-oUt）</translation>
    </message>
    <message>
        <source>Encoder signals (DP-Cod)</source>
        <translation>编码器信号（DP-Cod）</translation>
    </message>
    <message>
        <source>Alarm (DP-Err)</source>
        <translation>报警（DP-Err）</translation>
    </message>
    <message>
        <source>Phase A current (DP-IA)</source>
        <translation>A 相电流（DP-IA）</translation>
    </message>
    <message>
        <source>Phase C current (DP-IC)</source>
        <translation>C 相电流（DP-IC）</translation>
    </message>
    <message>
        <source>Invalid value &quot;%1&quot; for %2 (allowed: %3).</source>
        <translation>%2 的值“%1”无效（允许：%3）。</translation>
    </message>
    <message>
        <source>The servo-modbus protocol has no command to clear an alarm. Remove the cause, then reset the alarm at the drive (its panel, an alarm-reset input or a power cycle) and read the alarm again.</source>
        <translation>servo-modbus 协议没有清除报警的命令。请先排除故障原因，再在驱动器上复位报警（操作面板、报警复位输入或重新上电），然后重新读取报警。</translation>
    </message>
    <message>
        <source>The servo-modbus protocol reads and writes parameters and monitor values only; it has no motion, enable or stop commands. The axis runs from the drive&apos;s own control inputs (pulses, analog command, I/O).</source>
        <translation>servo-modbus 协议只能读写参数和监控值，没有运动、使能或停止命令。轴由驱动器自身的控制输入（脉冲、模拟量指令、I/O）控制运行。</translation>
    </message>
    <message>
        <source>The serial port is not open.</source>
        <translation>串口未打开。</translation>
    </message>
    <message>
        <source>Address %1 cannot answer: servo drives use 1..247 (0 is broadcast).</source>
        <translation>地址 %1 无法应答：伺服驱动器地址为 1..247（0 为广播）。</translation>
    </message>
    <message>
        <source>PA%1 does not exist: this drive has PA0..PA59.</source>
        <translation>PA%1 不存在：该驱动器的参数为 PA0..PA59。</translation>
    </message>
    <message>
        <source>Unknown channel &quot;%1&quot;. This drive offers: %2.</source>
        <translation>未知通道“%1”。该驱动器提供：%2。</translation>
    </message>
    <message>
        <source>PA%1 does not exist: this drive has PA0..PA59. Nothing was written.</source>
        <translation>PA%1 不存在：该驱动器的参数为 PA0..PA59。未写入任何数据。</translation>
    </message>
    <message>
        <source>PA%1 is given twice. Nothing was written.</source>
        <translation>PA%1 重复给出。未写入任何数据。</translation>
    </message>
    <message>
        <source>PA2 is the firmware version and cannot be written. Nothing was written.</source>
        <translation>PA2 为固件版本，不能写入。未写入任何数据。</translation>
    </message>
    <message>
        <source>%1 does not fit the 16-bit register of PA%2 (-32768..32767, or 0..65535 unsigned). Nothing was written.</source>
        <translation>%1 超出 PA%2 的 16 位寄存器范围（-32768..32767，无符号为 0..65535）。未写入任何数据。</translation>
    </message>
    <message>
        <source>Nothing was written.</source>
        <translation>未写入任何数据。</translation>
    </message>
    <message>
        <source>Unknown EE operation.</source>
        <translation>未知的 EE 操作。</translation>
    </message>
    <message>
        <source>The firmware version (PA2) could not be read, so the EE command format is unknown: %1 Choose the format by hand (option servo-modbus.eeFormat = legacy or new).</source>
        <translation>无法读取固件版本（PA2），因此 EE 命令格式未知：%1 请手动选择格式（选项 servo-modbus.eeFormat = legacy 或 new）。</translation>
    </message>
    <message>
        <source>The drive answered %1 with %2 instead of 0 (running) or %3 (done): the operation failed or another one is running.</source>
        <translation>驱动器对 %1 的应答为 %2，而不是 0（执行中）或 %3（完成）：操作失败或另一操作正在执行。</translation>
    </message>
    <message>
        <source>%1 did not finish within %2 s: the drive still reports it running after %3 polls. Do not switch the drive off; read its parameters again to see what was stored.</source>
        <translation>%1 在 %2 秒内未完成：查询 %3 次后驱动器仍报告执行中。请勿关闭驱动器电源；重新读取参数以确认保存的内容。</translation>
    </message>
    <message>
        <source>PA%1..PA%2: %3</source>
        <translation>PA%1..PA%2：%3</translation>
    </message>
</context>
<context>
    <name>dd::ServoModbusScanner</name>
    <message>
        <source>The serial port is not open.</source>
        <translation>串口未打开。</translation>
    </message>
    <message>
        <source>Cannot switch the port to %1 baud: the link is busy or closed. Stop other operations on this port before scanning.</source>
        <translation>无法将端口切换到 %1 波特：连接忙或已关闭。扫描前请停止该端口上的其他操作。</translation>
    </message>
    <message>
        <source>The scan was cancelled.</source>
        <translation>扫描已取消。</translation>
    </message>
    <message>
        <source>exception %1</source>
        <translation>异常应答 %1</translation>
    </message>
</context>
<context>
    <name>dd::ShuokeCanTransport</name>
    <message>
        <source>&quot;%1&quot; is not a CAN interface: write plugin:interface, e.g. socketcan:can0 or virtualcan:can0.</source>
        <translation>“%1”不是 CAN 接口：请按“插件:接口”填写，例如 socketcan:can0 或 virtualcan:can0。</translation>
    </message>
    <message>
        <source>%1, %2 kbit/s, Shuoke CAN</source>
        <translation>%1，%2 kbit/s，硕科 CAN</translation>
    </message>
    <message>
        <source>A command with %1 data bytes does not fit a CAN frame (at most %2).</source>
        <translation>含 %1 个数据字节的指令放不进一个 CAN 帧（最多 %2 个）。</translation>
    </message>
    <message>
        <source>The command cannot be encoded: %1</source>
        <translation>无法编码该指令：%1</translation>
    </message>
</context>
<context>
    <name>dd::ShuokeDiscovery</name>
    <message>
        <source>The link is not open.</source>
        <translation>连接未打开。</translation>
    </message>
    <message>
        <source>The scan was cancelled.</source>
        <translation>扫描已取消。</translation>
    </message>
    <message>
        <source>answers</source>
        <translation>有应答</translation>
    </message>
    <message>
        <source>The query-address broadcast could not be sent.</source>
        <translation>无法发送查询地址广播。</translation>
    </message>
    <message>
        <source>The link could not switch to %1 baud (it is busy).</source>
        <translation>连接无法切换到 %1 波特（连接忙）。</translation>
    </message>
</context>
<context>
    <name>dd::ShuokeDrive</name>
    <message>
        <source>A stop came before the motion command was sent: the axis was not started.</source>
        <translation>在运动指令发出之前收到了停止命令：轴未启动。</translation>
    </message>
    <message>
        <source>Shuoke drives have no enable command: the drive is enabled by its ENA input (shown as &quot;enable input&quot; in the status).</source>
        <translation>硕科驱动器没有使能命令：驱动器由 ENA 输入使能（在状态中显示为“使能输入”）。</translation>
    </message>
    <message>
        <source>Shuoke drives keep no alarm to clear: a refused command reports its failure code in the reply, and a limit switch clears when the axis leaves it.</source>
        <translation>硕科驱动器没有需要清除的报警：被拒绝的指令会在应答中返回故障代码，限位开关在轴离开后自动解除。</translation>
    </message>
    <message>
        <source>Shuoke drives store their settings themselves; there is no EEPROM command.</source>
        <translation>硕科驱动器会自行保存设置，没有 EEPROM 命令。</translation>
    </message>
    <message>
        <source>The %1 has no homing command (0x3E is for the M6505 and M4505S).</source>
        <translation>%1 没有回原点命令（0x3E 仅适用于 M6505 和 M4505S）。</translation>
    </message>
    <message>
        <source>0x%1 is not a Shuoke command.</source>
        <translation>0x%1 不是硕科指令。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; (command 0x%2) is not available on the %3.</source>
        <translation>%3 不支持“%1”（指令 0x%2）。</translation>
    </message>
    <message>
        <source>The drive has no link.</source>
        <translation>驱动器没有通讯连接。</translation>
    </message>
    <message>
        <source>Not sent to the drive at address %1: %2.</source>
        <translation>未发送到地址 %1 的驱动器：%2。</translation>
    </message>
    <message>
        <source>A relative move of %1 pulses is beyond the drive&apos;s 31-bit range.</source>
        <translation>相对运动 %1 个脉冲超出驱动器 31 位的范围。</translation>
    </message>
    <message>
        <source>The target %1 is beyond the drive&apos;s 31-bit range.</source>
        <translation>目标位置 %1 超出驱动器 31 位的范围。</translation>
    </message>
    <message>
        <source>The drive&apos;s position reply has %1 bytes.</source>
        <translation>驱动器的位置应答有 %1 个字节。</translation>
    </message>
    <message>
        <source>The move from %1 to %2 is beyond the drive&apos;s range.</source>
        <translation>从 %1 到 %2 的运动超出驱动器的范围。</translation>
    </message>
    <message>
        <source>This drive can only clear its position counter (set it to 0); only the M6505 sets its closed-loop position to a value.</source>
        <translation>该驱动器只能将位置计数清零（设为 0）；只有 M6505 可以将闭环位置设为指定值。</translation>
    </message>
    <message>
        <source>The position %1 is beyond the drive&apos;s range.</source>
        <translation>位置 %1 超出驱动器的范围。</translation>
    </message>
    <message>
        <source>A drive address is 1..247, not %1.</source>
        <translation>驱动器地址为 1..247，不能是 %1。</translation>
    </message>
    <message>
        <source>%1 is not a Shuoke address.</source>
        <translation>%1 不是硕科驱动器地址。</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Absolute position</source>
        <translation>绝对位置</translation>
    </message>
    <message>
        <source>Relative position</source>
        <translation>相对位置</translation>
    </message>
    <message>
        <source>Status bits (running, left limit, origin, right limit, enable)</source>
        <translation>状态位（运行、左限位、原点、右限位、使能）</translation>
    </message>
    <message>
        <source>Inputs IO1..IO5</source>
        <translation>输入 IO1..IO5</translation>
    </message>
    <message>
        <source>Inputs pulse, direction, enable, F1, F2</source>
        <translation>输入：脉冲、方向、使能、F1、F2</translation>
    </message>
    <message>
        <source>Closed-loop absolute position</source>
        <translation>闭环绝对位置</translation>
    </message>
    <message>
        <source>Closed-loop relative position</source>
        <translation>闭环相对位置</translation>
    </message>
    <message>
        <source>Position error (commanded - feedback)</source>
        <translation>位置偏差（指令 - 反馈）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a Shuoke channel.</source>
        <translation>“%1”不是硕科驱动器的通道。</translation>
    </message>
    <message>
        <source>The drive answered %1 data bytes for parameter %2 (%3 expected).</source>
        <translation>驱动器对参数 %2 应答了 %1 个数据字节（应为 %3 个）。</translation>
    </message>
    <message>
        <source>%1 is not a Shuoke parameter (the index is the SET command code).</source>
        <translation>%1 不是硕科参数（序号为设置指令的代码）。</translation>
    </message>
    <message>
        <source>%1 must be %2..%3; %4 was not sent.</source>
        <translation>%1 必须在 %2..%3 之间；%4 未发送。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>The drive&apos;s stored max-speed could not be read (%1), so a move at its own speed would overwrite it: nothing was moved. Move at speed 0 (the stored max-speed) or try again.</source>
        <translation>无法读取驱动器保存的最大速度（%1），以自身速度运行的定位会覆盖它：未进行任何运动。请以速度 0（即保存的最大速度）运动，或重试。</translation>
    </message>
    <message>
        <source>a reply of %1 bytes</source>
        <translation>%1 字节的应答</translation>
    </message>
</context>
<context>
    <name>dd::ShuokeOptions</name>
    <message>
        <source>The %1 framing needs a serial port, not a CAN interface.</source>
        <translation>%1 帧格式需要串口，而不是 CAN 接口。</translation>
    </message>
    <message>
        <source>The can framing needs a CAN interface (plugin:interface), not a serial port.</source>
        <translation>can 帧格式需要 CAN 接口（插件:接口），而不是串口。</translation>
    </message>
    <message>
        <source>%1 = &quot;%2&quot; is not a valid setting; use %3.</source>
        <translation>%1 = “%2”不是有效设置，请使用 %3。</translation>
    </message>
</context>
<context>
    <name>dd::ShuokePlcTransport</name>
    <message>
        <source>%1 @ %2 baud, Shuoke PLC mode (Modbus registers from 0x%3)</source>
        <translation>%1 @ %2 波特，硕科 PLC 模式（Modbus 寄存器起始 0x%3）</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has no register in PLC mode; use the RTU framing for it.</source>
        <translation>“%1”在 PLC 模式下没有寄存器，请使用 RTU 帧格式。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; maps to a read of 0 registers in PLC mode, which Modbus cannot send; use the RTU framing for it.</source>
        <translation>“%1”在 PLC 模式下对应读取 0 个寄存器，Modbus 无法发送，请使用 RTU 帧格式。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be sent in PLC mode: %2</source>
        <translation>“%1”无法在 PLC 模式下发送：%2</translation>
    </message>
    <message>
        <source>The command cannot be encoded: %1</source>
        <translation>无法编码该指令：%1</translation>
    </message>
    <message>
        <source>%1 (PLC mode: Modbus exception %2)</source>
        <translation>%1（PLC 模式：Modbus 异常 %2）</translation>
    </message>
</context>
<context>
    <name>dd::ShuokeSerialTransport</name>
    <message>
        <source>%1 @ %2 baud, Shuoke %3</source>
        <translation>%1 @ %2 波特，硕科 %3</translation>
    </message>
    <message>
        <source>The command cannot be encoded: %1</source>
        <translation>无法编码该指令：%1</translation>
    </message>
</context>
<context>
    <name>dd::ShuokeTransport</name>
    <message>
        <source>&quot;%1&quot; is accepted over RS232/RS485 only, not over CAN.</source>
        <translation>“%1”只能通过 RS232/RS485 发送，不能通过 CAN。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is accepted over CAN only.</source>
        <translation>“%1”只能通过 CAN 发送。</translation>
    </message>
    <message>
        <source>The drive at address %1 refused &quot;%2&quot; (command 0x%3): %4 (failure code 0x%5).</source>
        <translation>地址 %1 的驱动器拒绝了“%2”（指令 0x%3）：%4（故障代码 0x%5）。</translation>
    </message>
    <message>
        <source>The link is not open.</source>
        <translation>连接未打开。</translation>
    </message>
    <message>
        <source>The drive&apos;s reply could not be read: %1</source>
        <translation>无法读取驱动器的应答：%1</translation>
    </message>
    <message>
        <source>unknown failure code</source>
        <translation>未知故障代码</translation>
    </message>
</context>
<context>
    <name>dd::StatusBarWidget</name>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Link lost: %1</source>
        <translation>连接中断：%1</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>已连接：%1</translation>
    </message>
    <message numerus="yes">
        <source>%n link(s) open</source>
        <translation>
            <numerusform>已打开 %n 个连接</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 frames/s</source>
        <translation>%1 帧/秒</translation>
    </message>
    <message>
        <source>Errors: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <source>Retries: %1</source>
        <translation>重试：%1</translation>
    </message>
    <message>
        <source>Reset error and retry counts</source>
        <translation>错误和重试计数清零</translation>
    </message>
    <message>
        <source>Frames sent and received per second, all links</source>
        <translation>所有连接每秒收发的帧数</translation>
    </message>
    <message>
        <source>Discarded frames (bad checksum, garbage, late replies), lost links and failed operations. Right-click to reset.</source>
        <translation>丢弃的帧（校验错误、乱码、迟到的应答）、连接中断和失败的操作。右键单击可清零。</translation>
    </message>
    <message>
        <source>Requests sent again after a timeout or a corrupt reply</source>
        <translation>因超时或应答错误而重发的请求</translation>
    </message>
</context>
<context>
    <name>dd::StopAction</name>
    <message>
        <source>STOP</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Stop all drives on all connections (%1)</source>
        <translation>停止所有连接上的全部驱动器（%1）</translation>
    </message>
    <message>
        <source> or </source>
        <translation> 或 </translation>
    </message>
</context>
<context>
    <name>dd::TrafficLog</name>
    <message>
        <source>Cannot write %1: %2. Is the folder writable and the disk not full?</source>
        <translation>无法写入 %1：%2。请检查文件夹是否可写、磁盘是否已满。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2. The previous file, if any, is unchanged.</source>
        <translation>无法写入 %1：%2。原有文件（如有）保持不变。</translation>
    </message>
</context>
<context>
    <name>dd::TrendChannelPanel</name>
    <message>
        <source>Scale ×</source>
        <translation>比例 ×</translation>
    </message>
    <message>
        <source>Offset +</source>
        <translation>偏移 +</translation>
    </message>
    <message>
        <source>Axis, scale…</source>
        <translation>坐标轴、缩放…</translation>
    </message>
    <message>
        <source>The selected channel&apos;s axis, scale and offset (also: right click a channel)</source>
        <translation>所选通道的坐标轴、缩放和偏移（也可右键单击通道）</translation>
    </message>
    <message>
        <source>%1 — on the %2 axis. Right click: axis, scale and offset.</source>
        <translation>%1 — 位于%2坐标轴。右键单击：坐标轴、缩放和偏移。</translation>
    </message>
    <message>
        <source>left</source>
        <translation>左</translation>
    </message>
    <message>
        <source>right</source>
        <translation>右</translation>
    </message>
    <message>
        <source>Left axis</source>
        <translation>左坐标轴</translation>
    </message>
    <message>
        <source>Right axis</source>
        <translation>右坐标轴</translation>
    </message>
    <message>
        <source>Scale and offset…</source>
        <translation>缩放和偏移…</translation>
    </message>
    <message>
        <source>Reset scale and offset</source>
        <translation>重置缩放和偏移</translation>
    </message>
    <message>
        <source>Scale and offset: %1</source>
        <translation>缩放和偏移：%1</translation>
    </message>
    <message>
        <source>The plot draws value × scale + offset; readouts and exports show the real value.</source>
        <translation>曲线绘制 数值 × 缩放 + 偏移；读数和导出均为实际值。</translation>
    </message>
</context>
<context>
    <name>dd::TrendControls</name>
    <message>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Freeze the plot; recording continues in the background</source>
        <translation>冻结曲线显示，后台继续记录</translation>
    </message>
    <message>
        <source>Reset zoom</source>
        <translation>复位缩放</translation>
    </message>
    <message>
        <source>Show the selected time window again</source>
        <translation>重新显示所选时间窗口</translation>
    </message>
    <message>
        <source>&amp;Window:</source>
        <translation>时间窗口(&amp;W)：</translation>
    </message>
    <message>
        <source>10 s</source>
        <translation>10 秒</translation>
    </message>
    <message>
        <source>30 s</source>
        <translation>30 秒</translation>
    </message>
    <message>
        <source>1 min</source>
        <translation>1 分钟</translation>
    </message>
    <message>
        <source>2 min</source>
        <translation>2 分钟</translation>
    </message>
    <message>
        <source>5 min</source>
        <translation>5 分钟</translation>
    </message>
    <message>
        <source>10 min</source>
        <translation>10 分钟</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation>停止记录</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>记录</translation>
    </message>
    <message>
        <source>Recording: the drive is sampled whatever tab or drive is shown</source>
        <translation>正在记录：无论显示哪个选项卡或驱动器，都会持续采样该驱动器</translation>
    </message>
    <message>
        <source>Start recording the checked channels</source>
        <translation>开始记录勾选的通道</translation>
    </message>
    <message>
        <source>&amp;Rate:</source>
        <translation>采样率(&amp;R)：</translation>
    </message>
    <message>
        <source>How often the drive is read; the default is what the link can carry</source>
        <translation>读取驱动器的频率；默认值为链路所能承载的速率</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Save the checked channels&apos; real values as CSV, or the plot as an image</source>
        <translation>将勾选通道的实际值保存为 CSV，或将曲线保存为图像</translation>
    </message>
    <message>
        <source>CSV, whole recording…</source>
        <translation>CSV，整段记录…</translation>
    </message>
    <message>
        <source>CSV, visible window…</source>
        <translation>CSV，可见窗口…</translation>
    </message>
    <message>
        <source>Plot as PNG…</source>
        <translation>曲线图存为 PNG…</translation>
    </message>
    <message>
        <source>Plot as SVG…</source>
        <translation>曲线图存为 SVG…</translation>
    </message>
</context>
<context>
    <name>dd::TrendPanel</name>
    <message>
        <source>Trend</source>
        <translation>趋势</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s identity…</source>
        <translation>正在读取驱动器信息…</translation>
    </message>
    <message>
        <source>This drive offers no live values: %1</source>
        <translation>该驱动器不提供实时数值：%1</translation>
    </message>
    <message>
        <source>This drive reports no live channels.</source>
        <translation>该驱动器没有报告实时通道。</translation>
    </message>
    <message>
        <source>%1, address %2</source>
        <translation>%1，地址 %2</translation>
    </message>
</context>
<context>
    <name>dd::TrendView</name>
    <message>
        <source>Time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>Scaled value</source>
        <translation>缩放后的数值</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>–</source>
        <translation>–</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1: %2 %3</source>
        <translation>%1：%2 %3</translation>
    </message>
    <message numerus="yes">
        <source>%Ln sample(s) recorded</source>
        <translation>
            <numerusform>已记录 %Ln 个采样点</numerusform>
        </translation>
    </message>
    <message>
        <source>recording limit reached: oldest samples dropped</source>
        <translation>已达记录上限：最早的采样点已丢弃</translation>
    </message>
    <message>
        <source>Cannot save the plot image %1: %2. Check that the folder exists and is writable.</source>
        <translation>无法保存曲线图片 %1：%2。请检查文件夹是否存在且可写。</translation>
    </message>
    <message>
        <source>Export trend as CSV</source>
        <translation>将趋势导出为 CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Export plot as PNG</source>
        <translation>将曲线导出为 PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG 图片 (*.png)</translation>
    </message>
    <message>
        <source>Drag: zoom · wheel: zoom time (Shift: pan) · click: cursor A, Shift+click: cursor B · +/−, ←/→, Home: zoom, pan, reset · Del: remove cursors</source>
        <translation>拖动：缩放 · 滚轮：缩放时间（Shift：平移）· 单击：光标 A，Shift+单击：光标 B · +/−、←/→、Home：缩放、平移、复位 · Del：移除光标</translation>
    </message>
    <message>
        <source>%1 (left)</source>
        <translation>%1（左）</translation>
    </message>
    <message>
        <source>%1 (right)</source>
        <translation>%1（右）</translation>
    </message>
    <message>
        <source>no unit</source>
        <translation>无单位</translation>
    </message>
    <message>
        <source>Point at the plot to read values; click to set cursor A, Shift+click for B.</source>
        <translation>指向曲线可读取数值；单击设置光标 A，Shift+单击设置光标 B。</translation>
    </message>
    <message>
        <source>A: %1 s</source>
        <translation>A：%1 s</translation>
    </message>
    <message>
        <source>B: %1 s</source>
        <translation>B：%1 s</translation>
    </message>
    <message>
        <source>Δt = %1 s</source>
        <translation>Δt = %1 s</translation>
    </message>
    <message>
        <source>Δ %1: %2</source>
        <translation>Δ %1：%2</translation>
    </message>
    <message>
        <source>Δ %1: %2 %3</source>
        <translation>Δ %1：%2 %3</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>正在记录</translation>
    </message>
    <message>
        <source>view paused</source>
        <translation>视图已暂停</translation>
    </message>
    <message>
        <source>DriveDesk trend</source>
        <translation>DriveDesk 趋势图</translation>
    </message>
    <message>
        <source>DriveDesk trend: %1</source>
        <translation>DriveDesk 趋势图：%1</translation>
    </message>
    <message>
        <source>Recorded %1, window %2 s to %3 s</source>
        <translation>记录于 %1，窗口 %2 s 至 %3 s</translation>
    </message>
    <message>
        <source>Channels: %1</source>
        <translation>通道：%1</translation>
    </message>
    <message>
        <source>Export plot as SVG</source>
        <translation>将曲线图导出为 SVG</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>SVG 图像 (*.svg)</translation>
    </message>
    <message>
        <source>CSV saved to %1.</source>
        <translation>CSV 已保存到 %1。</translation>
    </message>
    <message>
        <source>Plot saved to %1.</source>
        <translation>曲线图已保存到 %1。</translation>
    </message>
</context>
<context>
    <name>dd::servocan</name>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>r/min</source>
        <translation>r/min</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>pulses</source>
        <translation>脉冲</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <source>Position command</source>
        <translation>位置指令</translation>
    </message>
    <message>
        <source>Position error</source>
        <translation>位置偏差</translation>
    </message>
    <message>
        <source>Torque</source>
        <translation>转矩</translation>
    </message>
    <message>
        <source>Output current</source>
        <translation>输出电流</translation>
    </message>
    <message>
        <source>Speed command</source>
        <translation>速度指令</translation>
    </message>
    <message>
        <source>Torque command</source>
        <translation>转矩指令</translation>
    </message>
    <message>
        <source>Rotor position</source>
        <translation>转子位置</translation>
    </message>
    <message>
        <source>Input IO</source>
        <translation>输入 IO</translation>
    </message>
    <message>
        <source>Output IO</source>
        <translation>输出 IO</translation>
    </message>
    <message>
        <source>Alarm code</source>
        <translation>报警代码</translation>
    </message>
    <message>
        <source>Bus voltage</source>
        <translation>母线电压</translation>
    </message>
</context>
<context>
    <name>dd::servomodbus</name>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Position, low part</source>
        <translation>位置（低位）</translation>
    </message>
    <message>
        <source>Position, high part</source>
        <translation>位置（高位）</translation>
    </message>
    <message>
        <source>Command position, low part</source>
        <translation>指令位置（低位）</translation>
    </message>
    <message>
        <source>Command position, high part</source>
        <translation>指令位置（高位）</translation>
    </message>
    <message>
        <source>Position error, low part</source>
        <translation>位置偏差（低位）</translation>
    </message>
    <message>
        <source>Position error, high part</source>
        <translation>位置偏差（高位）</translation>
    </message>
    <message>
        <source>Torque</source>
        <translation>转矩</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>电流</translation>
    </message>
    <message>
        <source>Pulse frequency</source>
        <translation>脉冲频率</translation>
    </message>
    <message>
        <source>Speed command</source>
        <translation>速度指令</translation>
    </message>
    <message>
        <source>Torque command</source>
        <translation>转矩指令</translation>
    </message>
    <message>
        <source>Rotor absolute position</source>
        <translation>转子绝对位置</translation>
    </message>
    <message>
        <source>Input terminals</source>
        <translation>输入端子</translation>
    </message>
    <message>
        <source>Output terminals</source>
        <translation>输出端子</translation>
    </message>
    <message>
        <source>Encoder signals</source>
        <translation>编码器信号</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <source>Phase A current</source>
        <translation>A 相电流</translation>
    </message>
    <message>
        <source>Phase C current</source>
        <translation>C 相电流</translation>
    </message>
    <message>
        <source>Reserved</source>
        <translation>保留</translation>
    </message>
    <message>
        <source>Store parameters to EEPROM</source>
        <translation>参数写入 EEPROM</translation>
    </message>
    <message>
        <source>Reload parameters from EEPROM</source>
        <translation>从 EEPROM 重新读取参数</translation>
    </message>
    <message>
        <source>Back up parameters</source>
        <translation>备份参数</translation>
    </message>
    <message>
        <source>Restore the parameter backup</source>
        <translation>恢复参数备份</translation>
    </message>
    <message>
        <source>Restore factory defaults</source>
        <translation>恢复出厂设置</translation>
    </message>
</context>
<context>
    <name>dd::shuoke</name>
    <message>
        <source>Handshake</source>
        <translation>握手</translation>
    </message>
    <message>
        <source>Query address</source>
        <translation>查询地址</translation>
    </message>
    <message>
        <source>Change address</source>
        <translation>更改地址</translation>
    </message>
    <message>
        <source>Get baud code</source>
        <translation>读取波特率代号</translation>
    </message>
    <message>
        <source>Set baud code</source>
        <translation>设置波特率代号</translation>
    </message>
    <message>
        <source>Set start speed</source>
        <translation>设置起始速度</translation>
    </message>
    <message>
        <source>Get start speed</source>
        <translation>读取起始速度</translation>
    </message>
    <message>
        <source>Set maximum speed</source>
        <translation>设置最大速度</translation>
    </message>
    <message>
        <source>Get maximum speed</source>
        <translation>读取最大速度</translation>
    </message>
    <message>
        <source>Set stop speed</source>
        <translation>设置停止速度</translation>
    </message>
    <message>
        <source>Get stop speed</source>
        <translation>读取停止速度</translation>
    </message>
    <message>
        <source>Set acceleration</source>
        <translation>设置加速度</translation>
    </message>
    <message>
        <source>Get acceleration</source>
        <translation>读取加速度</translation>
    </message>
    <message>
        <source>Set deceleration</source>
        <translation>设置减速度</translation>
    </message>
    <message>
        <source>Get deceleration</source>
        <translation>读取减速度</translation>
    </message>
    <message>
        <source>Set homing speed</source>
        <translation>设置回零速度</translation>
    </message>
    <message>
        <source>Get homing speed</source>
        <translation>读取回零速度</translation>
    </message>
    <message>
        <source>Move relative (signed pulses)</source>
        <translation>相对运动（带符号脉冲数）</translation>
    </message>
    <message>
        <source>Move relative (direction + 24-bit pulses)</source>
        <translation>相对运动（方向 + 24 位脉冲数）</translation>
    </message>
    <message>
        <source>Run at constant speed (signed)</source>
        <translation>恒速运行（带符号）</translation>
    </message>
    <message>
        <source>Run at constant speed (direction + 24-bit)</source>
        <translation>恒速运行（方向 + 24 位）</translation>
    </message>
    <message>
        <source>Change speed while running</source>
        <translation>运行中变速</translation>
    </message>
    <message>
        <source>Query speed</source>
        <translation>查询速度</translation>
    </message>
    <message>
        <source>Query absolute position</source>
        <translation>查询绝对位置</translation>
    </message>
    <message>
        <source>Clear absolute position</source>
        <translation>绝对位置清零</translation>
    </message>
    <message>
        <source>Query relative position</source>
        <translation>查询相对位置</translation>
    </message>
    <message>
        <source>Clear relative position</source>
        <translation>相对位置清零</translation>
    </message>
    <message>
        <source>Query status</source>
        <translation>查询状态</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>急停</translation>
    </message>
    <message>
        <source>Decelerate to stop</source>
        <translation>减速停止</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>回原点</translation>
    </message>
    <message>
        <source>Set PLC mapping base</source>
        <translation>设置 PLC 映射地址</translation>
    </message>
    <message>
        <source>Set IO substitution entry</source>
        <translation>设置 IO 替换项</translation>
    </message>
    <message>
        <source>Read IO substitution entry</source>
        <translation>读取 IO 替换项</translation>
    </message>
    <message>
        <source>Read inputs IO1..IO5</source>
        <translation>读取输入 IO1..IO5</translation>
    </message>
    <message>
        <source>Read pulse, direction, enable, F1, F2 inputs</source>
        <translation>读取脉冲、方向、使能、F1、F2 输入</translation>
    </message>
    <message>
        <source>Set speed step F</source>
        <translation>设置调速步长 F</translation>
    </message>
    <message>
        <source>Increase speed by F</source>
        <translation>速度增加 F</translation>
    </message>
    <message>
        <source>Decrease speed by F</source>
        <translation>速度减少 F</translation>
    </message>
    <message>
        <source>Factory reset</source>
        <translation>恢复出厂设置</translation>
    </message>
    <message>
        <source>Skip CRC check of received commands</source>
        <translation>接收指令时不校验 CRC</translation>
    </message>
    <message>
        <source>Fixed-length replies</source>
        <translation>定长应答</translation>
    </message>
    <message>
        <source>CAN frame format</source>
        <translation>CAN 帧格式</translation>
    </message>
    <message>
        <source>CAN bitrate code</source>
        <translation>CAN 波特率代号</translation>
    </message>
    <message>
        <source>Serial to CAN test echo</source>
        <translation>串口转 CAN 测试回显</translation>
    </message>
    <message>
        <source>CAN to serial test echo</source>
        <translation>CAN 转串口测试回显</translation>
    </message>
    <message>
        <source>Home (variant 2) / S-curve move (signed pulses)</source>
        <translation>回原点（方式 2）/ S 曲线运动（带符号脉冲数）</translation>
    </message>
    <message>
        <source>Home (variant 3) / S-curve move (direction + 24-bit)</source>
        <translation>回原点（方式 3）/ S 曲线运动（方向 + 24 位）</translation>
    </message>
    <message>
        <source>Closed loop: move by feedback pulses</source>
        <translation>闭环：按反馈脉冲数运动</translation>
    </message>
    <message>
        <source>Closed loop: move by geared pulses</source>
        <translation>闭环：按电子齿轮换算脉冲数运动</translation>
    </message>
    <message>
        <source>Closed loop: move to absolute position</source>
        <translation>闭环：运动到绝对位置</translation>
    </message>
    <message>
        <source>Closed loop: read absolute position</source>
        <translation>闭环：读取绝对位置</translation>
    </message>
    <message>
        <source>Closed loop: set or clear absolute position</source>
        <translation>闭环：设置或清零绝对位置</translation>
    </message>
    <message>
        <source>Closed loop: read relative position</source>
        <translation>闭环：读取相对位置</translation>
    </message>
    <message>
        <source>Closed loop: set or clear relative position</source>
        <translation>闭环：设置或清零相对位置</translation>
    </message>
    <message>
        <source>Encoder direction</source>
        <translation>编码器方向</translation>
    </message>
    <message>
        <source>Motion direction</source>
        <translation>运动方向</translation>
    </message>
    <message>
        <source>Accumulated-error correction</source>
        <translation>累计误差修正</translation>
    </message>
    <message>
        <source>Set gear numerator</source>
        <translation>设置电子齿轮分子</translation>
    </message>
    <message>
        <source>Get gear numerator</source>
        <translation>读取电子齿轮分子</translation>
    </message>
    <message>
        <source>Set gear denominator</source>
        <translation>设置电子齿轮分母</translation>
    </message>
    <message>
        <source>Get gear denominator</source>
        <translation>读取电子齿轮分母</translation>
    </message>
    <message>
        <source>Encoder A/B error tolerance</source>
        <translation>编码器 A/B 误差容限</translation>
    </message>
    <message>
        <source>Maximum pulses without encoder signal</source>
        <translation>无编码器信号时最大动作脉冲数</translation>
    </message>
    <message>
        <source>Receive timeout or wrong data length</source>
        <translation>接收超时或数据长度错误</translation>
    </message>
    <message>
        <source>Checksum error</source>
        <translation>校验错误</translation>
    </message>
    <message>
        <source>Unknown command</source>
        <translation>未知指令</translation>
    </message>
    <message>
        <source>Value out of range</source>
        <translation>数值超出范围</translation>
    </message>
    <message>
        <source>Command does not support broadcast</source>
        <translation>该指令不支持广播</translation>
    </message>
</context>
<context>
    <name>dd::BackupDiffTable</name>
    <message>
        <source>same</source>
        <translation>相同</translation>
    </message>
    <message>
        <source>different</source>
        <translation>不同</translation>
    </message>
    <message>
        <source>only in the file (not read from the drive)</source>
        <translation>仅在文件中（未从驱动器读到）</translation>
    </message>
    <message>
        <source>not in the file</source>
        <translation>文件中没有</translation>
    </message>
    <message>
        <source>write-only: the drive cannot report its value</source>
        <translation>只写：驱动器无法报告其数值</translation>
    </message>
    <message>
        <source>Read-only: a restore cannot change it.</source>
        <translation>只读：恢复时无法修改。</translation>
    </message>
    <message>
        <source>Changes how the drive communicates (address, baud rate): tick it to restore it too; then connect again with the new settings.</source>
        <translation>会改变驱动器的通讯方式（地址、波特率）：勾选后才会一并恢复；恢复后请用新设置重新连接。</translation>
    </message>
    <message>
        <source>not readable</source>
        <translation>不可读取</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>In the file</source>
        <translation>文件中的值</translation>
    </message>
    <message>
        <source>On the drive</source>
        <translation>驱动器中的值</translation>
    </message>
    <message>
        <source>Difference</source>
        <translation>差异</translation>
    </message>
</context>
<context>
    <name>dd::BackupPanel</name>
    <message>
        <source>Backup</source>
        <translation>备份</translation>
    </message>
    <message>
        <source>Save backup</source>
        <translation>保存备份</translation>
    </message>
    <message>
        <source>DriveDesk backups (*.json)</source>
        <translation>DriveDesk 备份文件 (*.json)</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s parameters…</source>
        <translation>正在读取驱动器参数…</translation>
    </message>
    <message>
        <source>No backup was saved:</source>
        <translation>未保存备份：</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n parameter(s) to %1.</source>
        <translation>
            <numerusform>已将 %n 个参数保存到 %1。</numerusform>
        </translation>
    </message>
    <message>
        <source>Open backup</source>
        <translation>打开备份</translation>
    </message>
    <message>
        <source>DriveDesk backups (*.json);;All files (*)</source>
        <translation>DriveDesk 备份文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>This file cannot be used, nothing was sent to the drive:</source>
        <translation>此文件无法使用，未向驱动器发送任何数据：</translation>
    </message>
    <message>
        <source>Reading the drive to compare it with the file…</source>
        <translation>正在读取驱动器，与文件比较…</translation>
    </message>
    <message>
        <source>The drive could not be compared with the file:</source>
        <translation>无法将驱动器与文件比较：</translation>
    </message>
    <message numerus="yes">
        <source>%n different</source>
        <translation>
            <numerusform>%n 个不同</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n write-only (cannot be compared)</source>
        <translation>
            <numerusform>%n 个只写（无法比较）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n not read from the drive</source>
        <translation>
            <numerusform>%n 个未从驱动器读到</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n the same</source>
        <translation>
            <numerusform>%n 个相同</numerusform>
        </translation>
    </message>
    <message>
        <source>Compared with the drive: %1.</source>
        <translation>与驱动器比较结果：%1。</translation>
    </message>
    <message>
        <source>Tick the parameters to restore first.</source>
        <translation>请先勾选要恢复的参数。</translation>
    </message>
    <message>
        <source>Restore cancelled: nothing was sent to the drive.</source>
        <translation>已取消恢复：未向驱动器发送任何数据。</translation>
    </message>
    <message numerus="yes">
        <source>Restoring %n parameter(s)…</source>
        <translation>
            <numerusform>正在恢复 %n 个参数…</numerusform>
        </translation>
    </message>
    <message>
        <source>Another firmware</source>
        <translation>固件版本不同</translation>
    </message>
    <message>
        <source>Restore the ticked parameters anyway?</source>
        <translation>仍要恢复所勾选的参数吗？</translation>
    </message>
    <message>
        <source>Change communication settings?</source>
        <translation>更改通讯设置？</translation>
    </message>
    <message>
        <source>%1 changes how the drive communicates (address, baud rate or framing). After the restore DriveDesk may no longer reach the drive with the current connection settings: connect again with the new ones.

Restore anyway?</source>
        <translation>%1 会改变驱动器的通讯方式（地址、波特率或帧格式）。恢复后 DriveDesk 可能无法再用当前连接设置访问驱动器，请用新设置重新连接。

仍要恢复吗？</translation>
    </message>
    <message>
        <source>Nothing was restored:</source>
        <translation>未恢复任何参数：</translation>
    </message>
    <message>
        <source>Write the ticked values from the file; the drive reads each back</source>
        <translation>写入文件中勾选的数值；驱动器逐个回读校验</translation>
    </message>
    <message>
        <source>%1 of %2 ticked</source>
        <translation>已勾选 %1 / %2</translation>
    </message>
    <message>
        <source>No file open.</source>
        <translation>未打开文件。</translation>
    </message>
    <message>
        <source>%1 — cannot be used: %2</source>
        <translation>%1 — 无法使用：%2</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message numerus="yes">
        <source>%1 — %2 drive at address %3, firmware %4, %n value(s), saved %5</source>
        <translation>
            <numerusform>%1 — %2 驱动器，地址 %3，固件 %4，%n 个数值，保存于 %5</numerusform>
        </translation>
    </message>
    <message>
        <source>The drive has firmware %1: a restore asks for confirmation.</source>
        <translation>驱动器固件为 %1：恢复前会要求确认。</translation>
    </message>
    <message>
        <source>Back up</source>
        <translation>备份</translation>
    </message>
    <message>
        <source>Read every parameter of the drive and save them to a file, to compare or restore them later — to this drive or to its replacement.</source>
        <translation>读取驱动器的全部参数并保存到文件，以便日后比较或恢复——恢复到本驱动器或替换它的新驱动器。</translation>
    </message>
    <message>
        <source>Save backup…</source>
        <translation>保存备份…</translation>
    </message>
    <message>
        <source>Compare and restore</source>
        <translation>比较与恢复</translation>
    </message>
    <message>
        <source>Open backup…</source>
        <translation>打开备份…</translation>
    </message>
    <message>
        <source>Show identical parameters</source>
        <translation>显示相同的参数</translation>
    </message>
    <message>
        <source>Tick all</source>
        <translation>全部勾选</translation>
    </message>
    <message>
        <source>Tick none</source>
        <translation>全部取消</translation>
    </message>
    <message>
        <source>Apply selected</source>
        <translation>应用所选</translation>
    </message>
    <message>
        <source>Wait until the drive has answered, then open %1 again.</source>
        <translation>请等待驱动器应答后，再打开 %1。</translation>
    </message>
    <message>
        <source>Only the settings changed from the defaults</source>
        <translation>仅保存与默认值不同的设置</translation>
    </message>
    <message>
        <source>Leaves out the settings equal to the dictionary&apos;s default and the read-only values; settings the dictionary gives no default for are kept. The file says it holds changes only, and restoring it touches only what it lists.</source>
        <translation>不保存等于字典默认值的设置和只读值；字典未给出默认值的设置予以保留。文件会注明只含改动，恢复它时只改动其中列出的参数。</translation>
    </message>
    <message>
        <source>Write to an energised drive?</source>
        <translation>写入已通电的驱动器？</translation>
    </message>
    <message>
        <source>Drive %1 is %2: a parameter changed while the axis is energised takes effect at once and can make it jerk or move.

Restore the ticked parameters anyway?</source>
        <translation>驱动器 %1 %2：在轴通电时更改的参数会立即生效，可能使轴抖动或运动。

仍要恢复勾选的参数吗？</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>正在运动</translation>
    </message>
    <message>
        <source>enabled</source>
        <translation>已使能</translation>
    </message>
</context>
<context>
    <name>dd::EePanel</name>
    <message>
        <source>EEPROM</source>
        <translation>EEPROM</translation>
    </message>
    <message>
        <source>Makes the working values permanent: the drive keeps them after a power cycle. Do this after changing parameters.</source>
        <translation>将当前工作参数永久保存：断电重启后驱动器仍保留这些值。修改参数后请执行此操作。</translation>
    </message>
    <message>
        <source>Replaces the working values with those stored in EEPROM. Changes not yet stored are lost.</source>
        <translation>用 EEPROM 中保存的值替换当前工作参数。尚未保存的修改将丢失。</translation>
    </message>
    <message>
        <source>Copies the working values into the drive&apos;s own backup area, replacing the previous copy there.</source>
        <translation>将当前工作参数复制到驱动器自身的备份区，覆盖备份区中原有的副本。</translation>
    </message>
    <message>
        <source>Replaces the working values with the copy in the drive&apos;s backup area. Changes not yet stored are lost; store the result with EE-Set to keep it after a power cycle.</source>
        <translation>用驱动器备份区中的副本替换当前工作参数。尚未保存的修改将丢失；如需断电后仍保留，请再执行 EE-Set。</translation>
    </message>
    <message>
        <source>Sets the working values and the EEPROM to the factory defaults. Every setting made on this drive is lost, possibly its address and baud rate too: save a backup file first (Backup tab).</source>
        <translation>将工作参数和 EEPROM 恢复为出厂设置。在本驱动器上做过的所有设置都将丢失，可能包括地址和波特率：请先保存备份文件（“备份”页）。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Run %1 on drive %2 now?</source>
        <translation>现在对驱动器 %2 执行 %1 吗？</translation>
    </message>
    <message>
        <source>%1 cancelled: nothing was sent to the drive.</source>
        <translation>已取消 %1：未向驱动器发送任何数据。</translation>
    </message>
    <message>
        <source>%1 running (%2 s): waiting for the drive to report completion. Do not switch the drive off.</source>
        <translation>%1 执行中（%2 秒）：等待驱动器报告完成。请勿断开驱动器电源。</translation>
    </message>
    <message>
        <source>%1 failed after %2 s: %3</source>
        <translation>%1 在 %2 秒后失败：%3</translation>
    </message>
    <message>
        <source>%1 done (%2 s): %3.</source>
        <translation>%1 已完成（%2 秒）：%3。</translation>
    </message>
    <message>
        <source>This drive has no EEPROM operations.</source>
        <translation>此驱动器没有 EEPROM 操作。</translation>
    </message>
    <message>
        <source>Waiting for the drive&apos;s identity…</source>
        <translation>正在等待驱动器的识别信息…</translation>
    </message>
    <message>
        <source>The drive works with its working values; EEPROM keeps a copy over a power cycle, and a backup area holds a second copy. Parameter writes change only the working values.</source>
        <translation>驱动器按工作参数运行；EEPROM 保存一份断电后仍保留的副本，备份区另存一份副本。写参数只改变工作参数。</translation>
    </message>
    <message>
        <source>EEPROM operations</source>
        <translation>EEPROM 操作</translation>
    </message>
    <message>
        <source>asks for confirmation</source>
        <translation>需要确认</translation>
    </message>
    <message>
        <source>The drive now works with other values: the Parameters tab reads them again.</source>
        <translation>驱动器现在使用其他参数值：参数页会重新读取它们。</translation>
    </message>
</context>
<context>
    <name>dd::ParameterEditCommand</name>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>Edit %1</source>
        <translation>编辑 %1</translation>
    </message>
</context>
<context>
    <name>dd::ParameterTableModel</name>
    <message>
        <source>the drive reads back %1</source>
        <translation>驱动器回读值为 %1</translation>
    </message>
    <message>
        <source>the drive did not accept the value</source>
        <translation>驱动器未接受该值</translation>
    </message>
    <message>
        <source>not written: the write stopped before this parameter</source>
        <translation>未写入：写入在此参数之前已中止</translation>
    </message>
    <message>
        <source>No parameter dictionary is loaded for this drive.</source>
        <translation>此驱动器未加载参数字典。</translation>
    </message>
    <message>
        <source>Read-only: the drive does not accept a new value.</source>
        <translation>只读：驱动器不接受新值。</translation>
    </message>
    <message>
        <source>Edited: the drive has %1. Write it to send the new value.</source>
        <translation>已修改：驱动器中为 %1。写入后才会发送新值。</translation>
    </message>
    <message>
        <source>Edited: not yet written to the drive.</source>
        <translation>已修改：尚未写入驱动器。</translation>
    </message>
    <message>
        <source>Double-click to edit (%1 to %2).</source>
        <translation>双击编辑（%1 至 %2）。</translation>
    </message>
    <message>
        <source>The drive cannot report this parameter: DriveDesk shows the value it last wrote.</source>
        <translation>驱动器无法报告此参数：DriveDesk 显示的是上次写入的值。</translation>
    </message>
    <message>
        <source>read/write</source>
        <translation>读写</translation>
    </message>
    <message>
        <source>read-only</source>
        <translation>只读</translation>
    </message>
    <message>
        <source>write-only</source>
        <translation>只写</translation>
    </message>
    <message>
        <source>not readable (last written: %1)</source>
        <translation>不可读取（上次写入：%1）</translation>
    </message>
    <message>
        <source>not readable</source>
        <translation>不可读取</translation>
    </message>
    <message>
        <source>written, verified</source>
        <translation>已写入，已校验</translation>
    </message>
    <message>
        <source>written (cannot be read back)</source>
        <translation>已写入（无法回读）</translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <source>not written</source>
        <translation>未写入</translation>
    </message>
    <message>
        <source>Index</source>
        <translation>编号</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>代号</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>On the drive</source>
        <translation>驱动器中</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>范围</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>访问</translation>
    </message>
    <message>
        <source>Last write</source>
        <translation>上次写入</translation>
    </message>
    <message>
        <source>Written to the drive&apos;s working memory but not saved to its EEPROM (EE-Set): the drive forgets it when switched off.</source>
        <translation>已写入驱动器的工作存储器，但尚未保存到 EEPROM（EE-Set）：驱动器断电后会丢失。</translation>
    </message>
    <message>
        <source>Undone: the value the drive had before the last write. Write it to restore it on the drive (the drive has %1 now).</source>
        <translation>已撤销：这是上次写入前驱动器中的值。写入它即可在驱动器上恢复（驱动器当前为 %1）。</translation>
    </message>
    <message>
        <source>undone: not yet written back</source>
        <translation>已撤销：尚未写回</translation>
    </message>
    <message>
        <source>%1 marks a value edited here that differs from the drive&apos;s; %2 an undone write, not yet written back; %3 a value written but not saved to EEPROM</source>
        <translation>%1 表示此处编辑的值与驱动器中的不同；%2 表示已撤销的写入，尚未写回；%3 表示已写入但未保存到 EEPROM 的值</translation>
    </message>
</context>
<context>
    <name>dd::ParameterValueValidator</name>
    <message>
        <source>No parameter dictionary is loaded for this drive.</source>
        <translation>此驱动器未加载参数字典。</translation>
    </message>
    <message>
        <source>Enter a value.</source>
        <translation>请输入数值。</translation>
    </message>
    <message>
        <source>“%1” is not a whole number (write it in decimal, or in hexadecimal as 0x…).</source>
        <translation>“%1”不是整数（请用十进制，或以 0x… 表示十六进制）。</translation>
    </message>
</context>
<context>
    <name>dd::ParametersPanel</name>
    <message>
        <source>Not accepted: %1 Nothing was sent to the drive.</source>
        <translation>不接受：%1 未向驱动器发送任何数据。</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>This drive has no parameter that can be read.</source>
        <translation>此驱动器没有可读取的参数。</translation>
    </message>
    <message numerus="yes">
        <source>Reading %n parameter(s)…</source>
        <translation>
            <numerusform>正在读取 %n 个参数…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Reading failed after %n parameter(s): %1</source>
        <translation>
            <numerusform>读取 %n 个参数后失败：%1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Read %n parameter(s) from the drive.</source>
        <translation>
            <numerusform>已从驱动器读取 %n 个参数。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n edited value(s) not yet written.</source>
        <translation>
            <numerusform>%n 个修改的值尚未写入。</numerusform>
        </translation>
    </message>
    <message>
        <source>Nothing to write: no selected row has an edited value.</source>
        <translation>无需写入：所选行中没有修改过的值。</translation>
    </message>
    <message>
        <source>Nothing to write: no value was edited.</source>
        <translation>无需写入：没有修改任何值。</translation>
    </message>
    <message>
        <source>Not written: %1 Nothing was sent to the drive.</source>
        <translation>未写入：%1 未向驱动器发送任何数据。</translation>
    </message>
    <message>
        <source>Not written: cancelled.</source>
        <translation>未写入：已取消。</translation>
    </message>
    <message numerus="yes">
        <source>Writing %n parameter(s)…</source>
        <translation>
            <numerusform>正在写入 %n 个参数…</numerusform>
        </translation>
    </message>
    <message>
        <source>Change communication settings?</source>
        <translation>更改通讯设置？</translation>
    </message>
    <message>
        <source>%1 changes how the drive communicates (address, baud rate or framing). After the change DriveDesk may no longer reach the drive with the current connection settings: connect again with the new ones.

Write anyway?</source>
        <translation>%1 会改变驱动器的通讯方式（地址、波特率或帧格式）。修改后 DriveDesk 可能无法再用当前连接设置访问驱动器，请用新设置重新连接。

仍要写入吗？</translation>
    </message>
    <message numerus="yes">
        <source>%n written and verified</source>
        <translation>
            <numerusform>%n 个已写入并校验</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n written (write-only, cannot be read back)</source>
        <translation>
            <numerusform>%n 个已写入（只写参数，无法回读）</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n failed or not written</source>
        <translation>
            <numerusform>%n 个失败或未写入</numerusform>
        </translation>
    </message>
    <message>
        <source>Read every parameter from the drive</source>
        <translation>从驱动器读取全部参数</translation>
    </message>
    <message>
        <source>Write the edited values of the selected rows; the drive reads each back</source>
        <translation>写入所选行中修改过的值；驱动器逐个回读校验</translation>
    </message>
    <message>
        <source>Write every edited value; the drive reads each back</source>
        <translation>写入全部修改过的值；驱动器逐个回读校验</translation>
    </message>
    <message>
        <source>Undo: %1</source>
        <translation>撤销：%1</translation>
    </message>
    <message>
        <source>Redo: %1</source>
        <translation>重做：%1</translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>Search by index, key or name</source>
        <translation>按编号、代号或名称搜索</translation>
    </message>
    <message>
        <source>Read all</source>
        <translation>全部读取</translation>
    </message>
    <message>
        <source>Write selected</source>
        <translation>写入所选</translation>
    </message>
    <message>
        <source>Write all changed</source>
        <translation>写入全部修改</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) changed on the drive by another tab; shown here.</source>
        <translation>
            <numerusform>另一个标签页在驱动器上更改了 %n 个值；已在此显示。</numerusform>
        </translation>
    </message>
    <message>
        <source>The drive&apos;s values were replaced (EEPROM operation): reading them again.</source>
        <translation>驱动器的参数值已被替换（EEPROM 操作）：正在重新读取。</translation>
    </message>
    <message>
        <source>Most names here are generic: the protocol document does not name these parameters. Load your drive&apos;s dictionary: File → &lt;a href=&quot;load&quot;&gt;Load dictionary…&lt;/a&gt;</source>
        <translation>此处的参数名称大多为通用名称：通讯协议文档未说明这些参数。请加载驱动器自己的参数字典：文件 → &lt;a href=&quot;load&quot;&gt;加载参数字典…&lt;/a&gt;</translation>
    </message>
    <message>
        <source>Dictionary not loaded: %1 The table is unchanged.</source>
        <translation>参数字典未加载：%1 表格保持不变。</translation>
    </message>
    <message numerus="yes">
        <source>Loaded the dictionary %1: %n parameter(s). Read all to see their values.</source>
        <translation>
            <numerusform>已加载参数字典 %1：%n 个参数。点击“全部读取”查看其数值。</numerusform>
        </translation>
    </message>
    <message>
        <source>Load a parameter dictionary</source>
        <translation>加载参数字典</translation>
    </message>
    <message>
        <source>DriveDesk dictionaries (*.json)</source>
        <translation>DriveDesk 参数字典 (*.json)</translation>
    </message>
</context>
<context>
    <name>dd::RestoreReportDialog</name>
    <message>
        <source>unknown: no answer to the read-back</source>
        <translation>未知：回读没有应答</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) could not be read back: what the drive holds is unknown; compare again.</source>
        <translation>
            <numerusform>%n 个参数无法回读：驱动器中的值未知，请重新比较。</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore report</source>
        <translation>恢复报告</translation>
    </message>
    <message>
        <source>Restore of %1:</source>
        <translation>%1 的恢复结果：</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>In the file</source>
        <translation>文件中的值</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>回读值</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>Detail</source>
        <translation>详情</translation>
    </message>
    <message>
        <source>not readable</source>
        <translation>不可读取</translation>
    </message>
    <message>
        <source>%1 selected: %2 written, %3 verified, %4 failed, %5 not attempted.</source>
        <translation>选中 %1 个：写入 %2 个，校验通过 %3 个，失败 %4 个，未执行 %5 个。</translation>
    </message>
    <message numerus="yes">
        <source>%n write-only parameter(s) written; the drive cannot report them back.</source>
        <translation>
            <numerusform>已写入 %n 个只写参数；驱动器无法回报其数值。</numerusform>
        </translation>
    </message>
    <message>
        <source>written, verified</source>
        <translation>已写入，已校验</translation>
    </message>
    <message>
        <source>written (cannot be read back)</source>
        <translation>已写入（无法回读）</translation>
    </message>
    <message>
        <source>written, but the drive reads back another value</source>
        <translation>已写入，但驱动器回读的值不同</translation>
    </message>
    <message>
        <source>failed: the drive did not accept it</source>
        <translation>失败：驱动器未接受</translation>
    </message>
    <message>
        <source>not attempted</source>
        <translation>未执行</translation>
    </message>
</context>
<context>
    <name>dd::BackupCommand</name>
    <message>
        <source>backup needs the file to write: backup -o FILE.</source>
        <translation>backup 需要指定要写入的文件：backup -o FILE。</translation>
    </message>
    <message>
        <source>backup: the folder %1 does not exist.</source>
        <translation>backup：文件夹 %1 不存在。</translation>
    </message>
    <message>
        <source>backup: %1 is a folder; give a file name.</source>
        <translation>backup：%1 是文件夹，请给出文件名。</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) saved to %1.</source>
        <translation>
            <numerusform>已将 %n 个参数保存到 %1。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) changed from the defaults saved to %1.</source>
        <translation>
            <numerusform>已将 %n 个与默认值不同的参数保存到 %1。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>dd::FileCommand</name>
    <message>
        <source>a backup file</source>
        <translation>一个备份文件</translation>
    </message>
    <message>
        <source>%1 is a backup of a %2 drive; this link is for %3 drives. A backup is never restored onto another family; to talk to a %2 drive add --family %2.</source>
        <translation>%1 是 %2 驱动器的备份，而此连接用于 %3 驱动器。备份绝不会恢复到其他系列的驱动器上；要与 %2 驱动器通讯，请加上 --family %2。</translation>
    </message>
    <message>
        <source>same</source>
        <translation>相同</translation>
    </message>
    <message>
        <source>differs</source>
        <translation>不同</translation>
    </message>
    <message>
        <source>drive value unknown</source>
        <translation>驱动器中的值未知</translation>
    </message>
    <message>
        <source>not in the file</source>
        <translation>文件中没有</translation>
    </message>
    <message>
        <source>write-only: drive value not readable</source>
        <translation>只写：无法读取驱动器中的值</translation>
    </message>
    <message>
        <source> (communication setting)</source>
        <translation>（通讯设置）</translation>
    </message>
    <message>
        <source>file %1  drive %2  %3</source>
        <translation>文件 %1  驱动器 %2  %3</translation>
    </message>
</context>
<context>
    <name>dd::DiffCommand</name>
    <message>
        <source>%1 differ, %2 same (%3).</source>
        <translation>%1 个不同，%2 个相同（%3）。</translation>
    </message>
</context>
<context>
    <name>dd::RestoreCommand</name>
    <message>
        <source>restore --only: %1 has no value in %2.</source>
        <translation>restore --only：%2 中没有 %1 的值。</translation>
    </message>
    <message>
        <source>restore --only: %1 is read-only.</source>
        <translation>restore --only：%1 为只读参数。</translation>
    </message>
    <message>
        <source>Finishing the restore in progress so that its report is complete; every write is verified as it goes.</source>
        <translation>正在完成进行中的恢复，以保证报告完整；每次写入都会随即回读校验。</translation>
    </message>
    <message>
        <source>verified</source>
        <translation>已校验</translation>
    </message>
    <message>
        <source>written (write-only: cannot be read back)</source>
        <translation>已写入（只写参数：无法回读）</translation>
    </message>
    <message>
        <source>WRITTEN, READ BACK %1</source>
        <translation>已写入，但回读值为 %1</translation>
    </message>
    <message>
        <source>NOT WRITTEN: %1</source>
        <translation>未写入：%1</translation>
    </message>
    <message>
        <source>NOT WRITTEN (not attempted)</source>
        <translation>未写入（未执行）</translation>
    </message>
    <message>
        <source>WRITTEN, NOT VERIFIED (no answer to the read-back)</source>
        <translation>已写入，未校验（回读无应答）</translation>
    </message>
    <message>
        <source>UNKNOWN: %1</source>
        <translation>状态未知：%1</translation>
    </message>
    <message>
        <source>would be written</source>
        <translation>将写入</translation>
    </message>
    <message>
        <source>%1 -&gt; %2  %3</source>
        <translation>%1 -&gt; %2  %3</translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation>已写入：%1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Not written: %1</source>
        <translation>未写入：%1</translation>
    </message>
    <message>
        <source>Unknown (read them again): %1</source>
        <translation>状态未知（请重新读取）：%1</translation>
    </message>
    <message>
        <source>The drive already matches %1; nothing to write.</source>
        <translation>驱动器已与 %1 一致，无需写入。</translation>
    </message>
    <message numerus="yes">
        <source>Dry run: %n parameter(s) would be written; nothing was sent.</source>
        <translation>
            <numerusform>试运行：将写入 %n 个参数；未发送任何数据。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) written and verified.</source>
        <translation>
            <numerusform>已写入并校验 %n 个参数。</numerusform>
        </translation>
    </message>
    <message>
        <source>The values are in the drive&apos;s RAM; `ee set` stores them to EEPROM.</source>
        <translation>这些值目前在驱动器的 RAM 中；用 `ee set` 将其存入 EEPROM。</translation>
    </message>
</context>
<context>
    <name>dd::Cli</name>
    <message>
        <source>Try: drivedesk-cli --help</source>
        <translation>请尝试：drivedesk-cli --help</translation>
    </message>
    <message>
        <source>No command given.</source>
        <translation>未给出命令。</translation>
    </message>
    <message>
        <source>Your own %1 dictionary was not used: %2</source>
        <translation>未使用您自己的 %1 参数字典：%2</translation>
    </message>
    <message>
        <source>Could not start the simulator: %1</source>
        <translation>无法启动模拟器：%1</translation>
    </message>
    <message>
        <source>simulated %1 drives %2 on %3</source>
        <translation>模拟 %1 驱动器，地址 %2，连接 %3</translation>
    </message>
    <message>
        <source>Could not open %1.</source>
        <translation>无法打开 %1。</translation>
    </message>
    <message>
        <source>There can be no %1 drive at address %2 on this link.</source>
        <translation>此连接上不可能有地址为 %2 的 %1 驱动器。</translation>
    </message>
    <message>
        <source>online</source>
        <translation>在线</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>离线</translation>
    </message>
    <message>
        <source>enabled</source>
        <translation>已使能</translation>
    </message>
    <message>
        <source>disabled</source>
        <translation>未使能</translation>
    </message>
    <message>
        <source>running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>alarm %1</source>
        <translation>报警 %1</translation>
    </message>
    <message>
        <source>%1 baud</source>
        <translation>%1 波特</translation>
    </message>
    <message>
        <source>%1 bit/s</source>
        <translation>%1 bit/s</translation>
    </message>
    <message>
        <source>address %1</source>
        <translation>地址 %1</translation>
    </message>
    <message>
        <source>firmware ?</source>
        <translation>固件 ?</translation>
    </message>
    <message>
        <source>firmware %1</source>
        <translation>固件 %1</translation>
    </message>
    <message>
        <source>--sim-state needs a file name.</source>
        <translation>--sim-state 需要文件名。</translation>
    </message>
    <message>
        <source>--dictionary needs a file name.</source>
        <translation>--dictionary 需要文件名。</translation>
    </message>
    <message>
        <source>--port needs a device, e.g. /dev/ttyUSB0 or COM3.</source>
        <translation>--port 需要指定设备，例如 /dev/ttyUSB0 或 COM3。</translation>
    </message>
    <message>
        <source>--can needs PLUGIN:INTERFACE, e.g. socketcan:can0.</source>
        <translation>--can 需要 PLUGIN:INTERFACE，例如 socketcan:can0。</translation>
    </message>
    <message>
        <source>Give either --port or --can, not both.</source>
        <translation>请给出 --port 或 --can 之一，不能同时给出。</translation>
    </message>
    <message>
        <source>--can &quot;%1&quot;: write PLUGIN:INTERFACE, e.g. socketcan:can0 or virtualcan:can0.</source>
        <translation>--can “%1”：请写成 PLUGIN:INTERFACE，例如 socketcan:can0 或 virtualcan:can0。</translation>
    </message>
    <message>
        <source>Unknown family &quot;%1&quot;. Families: %2.</source>
        <translation>未知的驱动器系列“%1”。可用系列：%2。</translation>
    </message>
    <message>
        <source>--framing %1 needs a serial port: use --port DEVICE.</source>
        <translation>--framing %1 需要串口：请使用 --port DEVICE。</translation>
    </message>
    <message>
        <source>--sim brings its own simulated bus: leave out --port and --can.</source>
        <translation>--sim 自带模拟总线：请去掉 --port 和 --can。</translation>
    </message>
    <message>
        <source>No link given: add --port DEVICE (e.g. /dev/ttyUSB0) or --can PLUGIN:INTERFACE (e.g. socketcan:can0), or --sim to use the built-in simulator.</source>
        <translation>未指定连接：请加上 --port DEVICE（例如 /dev/ttyUSB0）或 --can PLUGIN:INTERFACE（例如 socketcan:can0），或用 --sim 使用内置模拟器。</translation>
    </message>
    <message>
        <source>--option: write FAMILY.KEY=VALUE, e.g. --option shuoke.checksum=twos-complement (got &quot;%1&quot;).</source>
        <translation>--option：请写成 FAMILY.KEY=VALUE，例如 --option shuoke.checksum=twos-complement（实际为“%1”）。</translation>
    </message>
    <message>
        <source>--sim-drives: write ADDR[@BAUD],..., e.g. 3@19200,7.</source>
        <translation>--sim-drives：请写成 ADDR[@BAUD],...，例如 3@19200,7。</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] scan [--from A] [--to B] [--bauds 9600,19200,...]
Find the drives on the link. Without --bauds a serial scan tries --baud if given,
else the family&apos;s usual rates. Exit code 1 when no drive answered.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] scan [--from A] [--to B] [--bauds 9600,19200,...]
查找连接上的驱动器。串口扫描未给出 --bauds 时，若给出了 --baud 则只用该
波特率，否则尝试该系列的常用波特率。没有驱动器应答时退出码为 1。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] info
Identity, firmware, state, alarm and capabilities of the drive at --address.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] info
显示 --address 处驱动器的标识、固件、状态、报警和支持的功能。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] get PARAM ...
Read parameters. PARAM is an index (12), PA12, P12, or a name from the
dictionary.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] get PARAM ...
读取参数。PARAM 可以是序号（12）、PA12、P12 或参数字典中的名称。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] set PARAM=VALUE ...
Check every value against the dictionary (nothing is sent if one is bad),
write each, read it back and report whether it was verified.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] set PARAM=VALUE ...
按参数字典检查每个值（任一值无效则不发送任何数据），逐个写入并回读，
报告是否校验通过。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] ee set|rd|ba|rs|def
servo-modbus EEPROM operations, waiting for completion:
  set  store the parameters to EEPROM      rd   reload them from EEPROM
  ba   copy to the backup area             rs   restore the backup area
  def  factory defaults
</source>
        <translation>用法：drivedesk-cli [OPTIONS] ee set|rd|ba|rs|def
servo-modbus EEPROM 操作，并等待其完成：
  set  参数存入 EEPROM                  rd   从 EEPROM 重新读取参数
  ba   参数复制到备份区                 rs   从备份区恢复参数
  def  恢复出厂设置
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] monitor CHANNEL,... [--rate HZ] [--duration S] [-o FILE.csv]
Sample live values at --rate (default 10 Hz) until --duration ends or Ctrl-C.
-o writes CSV: a header of channel names with units, time in seconds.
See `channels` for the channel names of a drive.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] monitor CHANNEL,... [--rate HZ] [--duration S] [-o FILE.csv]
以 --rate（默认 10 Hz）采样实时值，直到 --duration 结束或按下 Ctrl-C。
-o 写入 CSV：表头为通道名称及单位，时间以秒为单位。
驱动器的通道名称见 `channels`。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] clear-alarm
Clear the alarm and read it again; exit code 1 if it is still there.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] clear-alarm
清除报警并重新读取；报警仍存在时退出码为 1。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] home [--positive] [--no-wait]
Search home, negative direction first (--positive: positive first), and wait
until the axis is at rest. Ctrl-C stops the axis.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] home [--positive] [--no-wait]
回零，先向负方向寻找原点（--positive：先向正方向），并等待轴静止。
Ctrl-C 停止轴。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] channels
The monitor channels this drive offers, with units.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] channels
该驱动器提供的监控通道及其单位。
</translation>
    </message>
    <message>
        <source>Unknown command &quot;%1&quot;. Commands: %2.</source>
        <translation>未知命令“%1”。可用命令：%2。</translation>
    </message>
    <message>
        <source>Unknown option %1 for &quot;%2&quot;. See: drivedesk-cli %2 --help</source>
        <translation>“%2”没有选项 %1。参见：drivedesk-cli %2 --help</translation>
    </message>
    <message>
        <source>Unknown option %1. See: drivedesk-cli --help</source>
        <translation>未知选项 %1。参见：drivedesk-cli --help</translation>
    </message>
    <message>
        <source>Option --%1 takes no value.</source>
        <translation>选项 --%1 不带值。</translation>
    </message>
    <message>
        <source>Option --%1 needs a value.</source>
        <translation>选项 --%1 需要一个值。</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a whole number.</source>
        <translation>%1：“%2”不是整数。</translation>
    </message>
    <message>
        <source>%1: %2 is out of range (allowed %3 to %4).</source>
        <translation>%1：%2 超出范围（允许 %3 到 %4）。</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number.</source>
        <translation>%1：“%2”不是数字。</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; has an empty item; write a comma-separated list such as 9600,19200.</source>
        <translation>%1：“%2”中有空项；请写成逗号分隔的列表，例如 9600,19200。</translation>
    </message>
    <message>
        <source>%1: expected on or off, not &quot;%2&quot;.</source>
        <translation>%1：应为 on 或 off，而不是“%2”。</translation>
    </message>
    <message>
        <source>Interrupted: stopping the axis.</source>
        <translation>已中断：正在停止轴。</translation>
    </message>
    <message>
        <source>Unknown language &quot;%1&quot; for --lang. Languages: en, zh_CN, system (the locale&apos;s).</source>
        <translation>--lang 的语言“%1”未知。可用语言：en、zh_CN、system（按区域设置）。</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] COMMAND [ARGS]
Commission servo and stepper drives from scripts.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] COMMAND [ARGS]
通过脚本调试伺服驱动器和步进驱动器。
</translation>
    </message>
    <message>
        <source>Output:
  --json                         one JSON document per command (JSON lines for
                                 monitor); failures too, with &quot;ok&quot;: false
  --trace                        print every frame, timestamped, to stderr
  --lang LANG                    language of messages, tables and help: en,
                                 zh_CN or system (default: the locale, from
                                 LANGUAGE, LC_ALL, LC_MESSAGES, LANG); --json
                                 output is never translated
  -h, --help                     this help; COMMAND --help for one command
  -V, --version                  the version
</source>
        <translation>输出：
  --json                         每条命令输出一个 JSON 文档（monitor 每行输出
                                 一个 JSON）；失败时也输出，带 &quot;ok&quot;: false
  --trace                        将每一帧加上时间戳打印到 stderr
  --lang LANG                    消息、表格和帮助的语言：en、zh_CN 或 system
                                 （默认：按区域设置，取自 LANGUAGE、LC_ALL、
                                 LC_MESSAGES、LANG）；--json 输出从不翻译
  -h, --help                     本帮助；COMMAND --help 查看单条命令的帮助
  -V, --version                  显示版本
</translation>
    </message>
    <message>
        <source>Exit codes:
  0  success
  1  the drive or the protocol failed (timeout, exception, verify mismatch)
  2  bad usage or bad input (nothing was sent)
  3  the port or bus could not be opened
</source>
        <translation>退出码：
  0  成功
  1  驱动器或协议出错（超时、异常应答、回读校验不一致）
  2  用法错误或输入错误（未发送任何数据）
  3  无法打开串口或总线
</translation>
    </message>
    <message>
        <source>Examples:
</source>
        <translation>示例：
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] stop [--emergency]
Stop the axis; --emergency: an emergency stop where the family has one.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] stop [--emergency]
停止轴；--emergency：急停（该系列支持时）。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] enable on|off
Servo enable on or off.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] enable on|off
伺服使能开或关。
</translation>
    </message>
    <message>
        <source>, </source>
        <comment>separator of the state words: online, enabled, idle</comment>
        <translation>，</translation>
    </message>
    <message>
        <source>Unknown framing &quot;%1&quot;. Framings: %2.</source>
        <translation>未知帧格式“%1”。可用帧格式：%2。</translation>
    </message>
    <message>
        <source>The %1 family has no %2 framing. Its framings: %3.</source>
        <translation>%1 系列没有 %2 帧格式。它的帧格式：%3。</translation>
    </message>
    <message>
        <source>--framing %1 needs a CAN bus: use --can PLUGIN:INTERFACE.</source>
        <translation>--framing %1 需要 CAN 总线：请使用 --can PLUGIN:INTERFACE。</translation>
    </message>
    <message>
        <source>The %1 family talks CAN: use --can PLUGIN:INTERFACE instead of --port.</source>
        <translation>%1 系列使用 CAN 通讯：请用 --can PLUGIN:INTERFACE 代替 --port。</translation>
    </message>
    <message>
        <source>The %1 family talks RS485: use --port DEVICE instead of --can.</source>
        <translation>%1 系列使用 RS485 通讯：请用 --port DEVICE 代替 --can。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; works on one drive: give one --address. backup, restore and diff take several (--address 1,2,5).</source>
        <translation>&quot;%1&quot; 只作用于一台驱动器：请只给一个 --address。backup、restore 和 diff 可接受多个（--address 1,2,5）。</translation>
    </message>
    <message>
        <source>--sim-resonance-hz must be a frequency from 1 to 1000 Hz, not &quot;%1&quot;.</source>
        <translation>--sim-resonance-hz 必须是 1 到 1000 Hz 之间的频率，而不是“%1”。</translation>
    </message>
    <message>
        <source>--address: %1 is given twice.</source>
        <translation>--address：%1 重复给出。</translation>
    </message>
    <message>
        <source>Link and drive:
  --family servo-can|servo-modbus|shuoke   drive family (default: servo-can with
                                 --can, servo-modbus otherwise)
  --port DEVICE                  serial port, e.g. /dev/ttyUSB0 or COM3
  --can PLUGIN:INTERFACE         CAN bus, e.g. socketcan:can0, virtualcan:can0
  --baud N                       serial baud rate (default: the family&apos;s)
  --bitrate N                    CAN bitrate (default: the family&apos;s)
  --framing rtu|ascii|can|plc    shuoke framing (default: rtu on a port, can on CAN)
  --address N                    the drive to talk to (default 1)
  --timeout MS                   reply allowance beyond the wire time
  --retries N                    extra attempts after a timeout
  --dictionary FILE              parameter dictionary (names, ranges, units);
                                 &quot;simulator&quot;: the simulator&apos;s, with its loop gains
  --option FAMILY.KEY=VALUE      a family setting where the protocol documents are
                                 ambiguous, e.g. shuoke.checksum=twos-complement,
                                 servo-modbus.positionRule=decimal10000 (repeatable;
                                 see docs/cli.md)
  --sim                          use the built-in simulator instead of hardware
                                 (see &quot;Simulator&quot; below)
</source>
        <translation>连接与驱动器：
  --family servo-can|servo-modbus|shuoke   驱动器系列（默认：有 --can 时为
                                 servo-can，否则为 servo-modbus）
  --port DEVICE                  串口，例如 /dev/ttyUSB0 或 COM3
  --can PLUGIN:INTERFACE         CAN 总线，例如 socketcan:can0、virtualcan:can0
  --baud N                       串口波特率（默认：该系列的默认值）
  --bitrate N                    CAN 波特率（默认：该系列的默认值）
  --framing rtu|ascii|can|plc    shuoke 帧格式（默认：串口为 rtu，CAN 为 can）
  --address N                    要通讯的驱动器地址（站号，默认 1）
  --timeout MS                   线路传输时间之外的应答等待余量
  --retries N                    超时后的额外重试次数
  --dictionary FILE              参数字典（名称、范围、单位）；
                                 &quot;simulator&quot;：模拟器的参数字典，含其环路增益
  --option FAMILY.KEY=VALUE      协议文档未明确之处的系列设置，例如
                                 shuoke.checksum=twos-complement、
                                 servo-modbus.positionRule=decimal10000
                                 （可重复；见 docs/cli.md）
  --sim                          使用内置模拟器代替硬件（见下文“模拟器”）
</translation>
    </message>
    <message>
        <source>  ping [--count N]               link health: turnaround, timeouts, errors, and
                                 the timeout and gap to use; exit 1 if no answer
</source>
        <translation>  ping [--count N]               链路健康：往返时间、超时、错误，以及
                                 建议的超时和间隔；无应答时退出码为 1
</translation>
    </message>
    <message>
        <source>Simulator:
  --sim runs the command against simulated drives of --family inside this
  process, with nothing plugged in: serial families on a pseudo-terminal,
  CAN families on Qt&apos;s virtualcan bus. --port/--can are then not needed.
  --sim-drives ADDR[@BAUD],...   the simulated drives (default: one at --address,
                                 at --baud); e.g. --sim-drives 3@19200,7@38400
  --sim-state FILE               keep the simulated drives&apos; state (parameters,
                                 EEPROM, position, alarm) in FILE between runs
  --sim-motion                   the simulated drives move on their own (for
                                 monitor demos; where the family&apos;s simulator can)
  --sim-resonance-hz F           the simulated load resonates at F Hz (1..1000)
  With --sim the simulator&apos;s dictionary is used: it names the simulator&apos;s own
  loop gains in its &quot;tuning&quot; group (docs/tuning.md).
</source>
        <translation>模拟器：
  --sim 在本进程内对 --family 系列的模拟驱动器执行命令，无需连接任何硬件：
  串口系列使用伪终端，CAN 系列使用 Qt 的 virtualcan 总线。此时不需要
  --port/--can。
  --sim-drives ADDR[@BAUD],...   模拟的驱动器（默认：在 --address 处一台，
                                 波特率为 --baud）；
                                 例如 --sim-drives 3@19200,7@38400
  --sim-state FILE               在多次运行之间把模拟驱动器的状态（参数、
                                 EEPROM、位置、报警）保存在 FILE 中
  --sim-motion                   模拟驱动器自行运动（用于 monitor 演示；
                                 仅限该系列的模拟器支持时）
  --sim-resonance-hz F           模拟负载在 F Hz 处发生谐振（1..1000）
  使用 --sim 时采用模拟器的参数字典：其 &quot;tuning&quot; 组列出模拟器自身的
  环路增益（docs/tuning.md）。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] backup -o FILE [--changed-only]
       drivedesk-cli [OPTIONS] (--all | --address 1,2,5) backup -o DIR [--from A] [--to B]
Read every readable parameter and save them to a backup file (saved
atomically: an interrupted backup never leaves a half-written file).
--changed-only keeps only the settings that differ from the dictionary&apos;s
defaults (the file says so; its restore touches only those). Several drives
(--all: every drive a scan finds): one file per drive, FAMILY-ADDRESS.json,
and DIR/index.json; the exit code is the worst drive&apos;s.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] backup -o FILE [--changed-only]
      drivedesk-cli [OPTIONS] (--all | --address 1,2,5) backup -o DIR [--from A] [--to B]
读取全部可读参数并保存到备份文件（原子保存：备份中断也不会留下写了
一半的文件）。
--changed-only 只保存与参数字典默认值不同的设置（文件中有标记；恢复它
只会改动这些参数）。多台驱动器（--all：扫描找到的每一台）：每台一个文件
FAMILY-ADDRESS.json，另有 DIR/index.json；退出码取最差的那台驱动器的。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] diff FILE
       drivedesk-cli [OPTIONS] diff A B
Compare the drive with a backup file, or any two sources: a backup file,
drive (the drive at --address), drive:ADDRESS or defaults. Two files need
no link. Sources of different families are refused. Exit code as diff(1):
0 equal, 1 different, 2 trouble (bad input, a drive that did not answer).
</source>
        <translation>用法：drivedesk-cli [OPTIONS] diff FILE
      drivedesk-cli [OPTIONS] diff A B
比较驱动器与备份文件，或任意两个来源：备份文件、drive（--address 指定的
驱动器）、drive:地址 或 defaults（默认值）。比较两个文件无需连接。不同系列
的来源一律拒绝。退出码同 diff(1)：0 相同，1 不同，2 出错（输入有误、驱动器
无应答）。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] ping [--count N]
Ask the drive for its status N times (default 10), one request at a time, and
report the link&apos;s health: turnaround min / median / max, timeouts, checksum
errors, late or duplicated replies, retries, and the reply allowance (--timeout)
and gap between requests it recommends. Exit code 1 when the drive answered none.
</source>
        <translation>用法：drivedesk-cli [选项] ping [--count N]
逐个向驱动器查询 N 次状态（默认 10 次），并报告链路健康状况：
往返时间的最小值 / 中位数 / 最大值、超时、校验错误、迟到或重复的应答、
重试次数，以及建议的应答余量（--timeout）和请求间隔。
驱动器一次也没有应答时退出码为 1。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli runs RUN.ddrun [RUN2.ddrun ...]
The runs&apos; metrics side by side, and the tuning parameters that differ between
consecutive runs with what the metrics did. Reads files only.
</source>
        <translation>用法：drivedesk-cli runs RUN.ddrun [RUN2.ddrun ...]
并列显示各次运行的指标，以及相邻两次运行之间不同的整定参数和指标随之
发生的变化。只读取文件。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] apply-run RUN.ddrun [--dry-run] [--force]
Write the tuning parameters the run was taken with (its snapshot) back to the
drive, as restore does: only those that differ from the drive, each read back
and reported verified or not. A run of another family, or whose parameters the
dictionary does not know as such, is refused (exit 2, nothing sent); another
firmware only with --force. --dry-run shows what would be written.
</source>
        <translation>用法：drivedesk-cli [选项] apply-run RUN.ddrun [--dry-run] [--force]
将运行记录采集时的调谐参数（其快照）写回驱动器，方式与 restore 相同：只写入与
驱动器不同的参数，每个都回读并报告是否校验通过。其他系列的运行记录，或参数字典
不再认得其参数的运行记录会被拒绝（退出码 2，不发送任何内容）；固件不同时需加
--force。--dry-run 显示将要写入的内容。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli spectrum RUN.ddrun CHANNEL [--peaks N] [--from HZ] [--between T1:T2]
The channel&apos;s amplitude spectrum (Hann window; resolution stated) and its N
highest peaks (default 5), at HZ and above with --from, of the samples from T1
to T2 seconds after the trigger with --between (e.g. after a step&apos;s own
transient, where its ringing shows a resonance). Reads files only.
</source>
        <translation>用法：drivedesk-cli spectrum RUN.ddrun CHANNEL [--peaks N] [--from HZ] [--between T1:T2]
该通道的幅值频谱（Hann 窗；注明分辨率）及其 N 个最高峰值（默认 5 个），
使用 --from 时只取 HZ 及以上的峰值，使用 --between 时只取触发后 T1 到 T2 秒的
采样（例如阶跃自身的过渡过程之后，其振荡会显出共振）。只读取文件。
</translation>
    </message>
    <message>
        <source>  report -o RECORD.pdf [--all] [--runs RUN.ddrun,...] [--header FILE.json]
         [--json-out RECORD.json]
                                 the commissioning record (PDF and JSON)
</source>
        <translation>  report -o RECORD.pdf [--all] [--runs RUN.ddrun,...] [--header FILE.json]
         [--json-out RECORD.json]
                                 调试记录（PDF 与 JSON）
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] restore FILE [--dry-run] [--only PARAM,...] [--force]
Write the parameters that differ from the file and verify each by reading it
back. The file is checked completely before anything is sent. A file from
another family is refused; from another firmware only with --force.
--dry-run shows what would be written. On failure the report says exactly
which parameters were written and which were not.
With --all (every drive a scan finds) or --address 1,2,5 the file goes to
each drive at its own address; communication settings are never copied
unless --only names them. --stop-on-failure: one drive after the other,
none after the first that fails. The exit code is the worst drive&apos;s.
restore DIR [--address 1,2,5]: a folder written by backup --all -o DIR put
back, every drive its index.json lists (or those of --address) from its own
file, at its address; each file is checked to be that drive&apos;s before anything
is sent.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] restore FILE [--dry-run] [--only PARAM,...] [--force]
写入与文件不同的参数，并逐个回读校验。发送任何数据之前会完整检查文件。
其他系列的备份文件一律拒绝；其他固件版本的备份文件须加 --force。
--dry-run 只显示将写入的内容。失败时报告会准确列出哪些参数已写入、
哪些未写入。
使用 --all（扫描找到的每一台）或 --address 1,2,5 时，文件写入每台驱动器各自
的地址；通信设置除非在 --only 中指明，否则从不复制。--stop-on-failure：逐台
进行，第一台失败后不再继续。退出码取最差的那台驱动器的。
restore DIR [--address 1,2,5]：将 backup --all -o DIR 写出的文件夹恢复回去，
index.json 中列出的每台驱动器（或 --address 指定的驱动器）各用自己的文件、
按其地址恢复；发送任何数据之前会逐个确认文件属于该驱动器。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] report -o RECORD.pdf [--all] [--runs RUN.ddrun,...]
                     [--header FILE.json] [--json-out RECORD.json] [--page-size a4|letter]
The commissioning record of the drive at --address (--all: of every drive a scan
of the link finds): identity, firmware, link, the parameters that differ from the
dictionary&apos;s defaults (all of them in the appendix), the last restore or write
verification, alarms, link health and backup files, as a PDF in the language of
--lang, and the same as JSON whose SHA-256 the PDF prints (docs/record.md).
--all [--from A] [--to B]: the scan&apos;s address range (default: the family&apos;s).
--header: machine, customer, site, engineer, notes from a JSON file.
--runs RUN.ddrun,...: tuning runs (capture or step test files) shown with the drive
they were taken on: plot, metrics, parameter snapshot. A bad run file, or one of a
drive not in the record, exits 2 with the reason and writes nothing.
</source>
        <translation>用法：drivedesk-cli [选项] report -o RECORD.pdf [--all] [--runs RUN.ddrun,...]
                     [--header FILE.json] [--json-out RECORD.json] [--page-size a4|letter]
生成 --address 所指驱动器的调试记录（--all：扫描链路找到的全部驱动器）：身份、固件、
链路、与字典默认值不同的参数（附录中列出全部参数）、最近一次恢复或写入的校验结果、
报警、链路状况和备份文件；PDF 使用 --lang 的语言，另有内容相同的 JSON，
PDF 中印有该 JSON 的 SHA-256（docs/record.md）。
--all [--from A] [--to B]：扫描的地址范围（默认：该系列的范围）。
--header：从 JSON 文件读取机器、客户、现场、工程师、备注。
--runs RUN.ddrun,...：调试运行（采集或阶跃测试文件），显示在其所测的驱动器下：
曲线、指标、参数快照。运行文件有误，或其驱动器不在记录中时，以退出码 2 结束并说明原因，
不写任何文件。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] capture CHANNEL,... [--trigger EXPR] [--pre 25%|0.1s]
          [--duration S] [--mode single|auto] [--timeout S] [--notes TEXT] -o RUN.ddrun
EXPR: rise:CHANNEL:VALUE | fall:CHANNEL:VALUE | either:CHANNEL:VALUE
      | above:CHANNEL:VALUE | below:CHANNEL:VALUE | alarm | now (default)
Samples as fast as the link allows; --pre is the part of the record before the
trigger, with its unit: a percentage (25%) or seconds (0.1s) (default 0), as in
step; --duration the record (default 1 s); auto captures anyway
after --timeout seconds (default 1). Saves the samples and the drive&apos;s tuning
parameters (read from it) to RUN.ddrun (docs/tuning.md).
</source>
        <translation>用法：drivedesk-cli [OPTIONS] capture CHANNEL,... [--trigger EXPR] [--pre 25%|0.1s]
          [--duration S] [--mode single|auto] [--timeout S] [--notes TEXT] -o RUN.ddrun
EXPR: rise:CHANNEL:VALUE | fall:CHANNEL:VALUE | either:CHANNEL:VALUE
      | above:CHANNEL:VALUE | below:CHANNEL:VALUE | alarm | now（默认）
以连接允许的最快速度采样；--pre 为记录中触发之前的部分，须带单位：百分比（25%）
或秒（0.1s）（默认 0），与 step 相同；--duration 为记录时长（默认 1 s）；auto
模式在 --timeout 秒（默认 1）后即使未触发也会采集。将采样数据和驱动器的整定参数
（从驱动器读取）保存到 RUN.ddrun（docs/tuning.md）。
</translation>
    </message>
    <message>
        <source>--pre needs its unit: a percentage of the record (e.g. --pre 25%) or seconds before the trigger (e.g. --pre 0.1s), not &quot;%1&quot;.</source>
        <translation>--pre 需要带单位：记录的百分比（例如 --pre 25%）或触发前的秒数（例如 --pre 0.1s），而不是“%1”。</translation>
    </message>
    <message>
        <source>--pre: &quot;%1&quot; must be a percentage from 0%% to %2%%.</source>
        <translation>--pre：“%1”必须是 0%% 到 %2%% 之间的百分比。</translation>
    </message>
    <message>
        <source>--pre: &quot;%1&quot; must be seconds from 0s to %2s.</source>
        <translation>--pre：“%1”必须是 0s 到 %2s 之间的秒数。</translation>
    </message>
    <message>
        <source>Commands:
  scan [--from A] [--to B] [--bauds 9600,19200,...]
                                 find drives: family, address, baud, firmware, state
  info                           identity, firmware, state, alarm, capabilities
  get PARAM ...                  read parameters; PARAM = 12, PA12, P12 or a name
  set PARAM=VALUE ...            validate, write, read back, report verified or not
  backup -o FILE [--changed-only] every readable parameter to a backup file
  backup (--all | --address 1,2,5) -o DIR
                                 one file per drive, FAMILY-ADDRESS.json, and index.json
  diff FILE | diff A B           compare; A, B = FILE, drive, drive:ADDRESS or defaults
  restore FILE [--dry-run] [--only PARAM,...] [--force]
                                 write the differences, verify each
  restore FILE (--all | --address 1,2,5) [--stop-on-failure]
                                 the same to several drives, each at its address
  ee set|rd|ba|rs|def            servo-modbus EEPROM operations; waits for them
  monitor CHANNEL,... [--rate HZ] [--duration S] [-o FILE.csv]
                                 sample live values (Ctrl-C ends)
  jog SPEED [--duration S] [--enable]  run, then stop; Ctrl-C or any error stops at once
  move (--by N | --to N) [--speed V] [--no-wait] [--enable]
                                 move, and wait until the axis is at rest
  stop [--emergency]             stop (emergency stop where the family has one)
  enable on|off                  servo enable on or off
  clear-alarm                    clear the alarm and check that it is gone
  home [--positive] [--no-wait]  homing, negative direction first
  channels                       the monitor channels this drive offers
  capture CHANNEL,... [--trigger EXPR] [--pre 25%|0.1s] [--duration S]
          [--mode single|auto] [--timeout S] -o RUN.ddrun
                                 triggered capture to a run file
  step velocity SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]
  step position DISTANCE --speed V --max-travel N [-o RUN.ddrun]
  step reversal SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]
                                 step-response test within limits, with metrics
  runs RUN.ddrun [RUN2.ddrun ...] metrics side by side, parameter differences
  apply-run RUN.ddrun [--dry-run] [--force]
                                 write the run&apos;s tuning parameters where they differ
  spectrum RUN.ddrun CHANNEL [--peaks N]
                                 a channel&apos;s spectrum and its peaks
</source>
        <translation>命令：
  scan [--from A] [--to B] [--bauds 9600,19200,...]
                                 查找驱动器：系列、地址、波特率、固件、状态
  info                           标识、固件、状态、报警、支持的功能
  get PARAM ...                  读取参数；PARAM 为 12、PA12、P12 或名称
  set PARAM=VALUE ...            检查取值、写入、回读，报告是否校验通过
  backup -o FILE [--changed-only] 将全部可读参数备份到文件
  backup (--all | --address 1,2,5) -o DIR
                                 每台驱动器一个文件 FAMILY-ADDRESS.json，另有 index.json
  diff FILE | diff A B           比较；A、B 为 FILE、drive、drive:ADDRESS 或 defaults
  restore FILE [--dry-run] [--only PARAM,...] [--force]
                                 写入有差异的参数，并逐个校验
  restore FILE (--all | --address 1,2,5) [--stop-on-failure]
                                 同上，写入多台驱动器，各用其自己的地址
  ee set|rd|ba|rs|def            servo-modbus EEPROM 操作；等待其完成
  monitor CHANNEL,... [--rate HZ] [--duration S] [-o FILE.csv]
                                 采样实时值（Ctrl-C 结束）
  jog SPEED [--duration S] [--enable]  点动运行后停止；Ctrl-C 或任何错误立即停止
  move (--by N | --to N) [--speed V] [--no-wait] [--enable]
                                 定位运动，并等待轴静止
  stop [--emergency]             停止（该系列支持时可急停）
  enable on|off                  伺服使能开或关
  clear-alarm                    清除报警并确认报警已消除
  home [--positive] [--no-wait]  回零，先向负方向
  channels                       该驱动器提供的监控通道
  capture CHANNEL,... [--trigger EXPR] [--pre 25%|0.1s] [--duration S]
          [--mode single|auto] [--timeout S] -o RUN.ddrun
                                 触发采集，保存为运行记录文件
  step velocity SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]
  step position DISTANCE --speed V --max-travel N [-o RUN.ddrun]
  step reversal SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]
                                 在限值内进行阶跃响应测试，给出指标
  runs RUN.ddrun [RUN2.ddrun ...] 并列比较指标，列出参数差异
  apply-run RUN.ddrun [--dry-run] [--force]
                                 将运行记录的调谐参数写入有差异之处
  spectrum RUN.ddrun CHANNEL [--peaks N]
                                 通道的频谱及其峰值
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] jog SPEED [--duration S] [--enable]
Run at SPEED (negative: the other way) until --duration ends, Ctrl-C, SIGTERM
or any error, then stop. Without --duration it runs until Ctrl-C. A second
Ctrl-C sends an emergency stop where the family has one.
--enable: servo-can&apos;s motion commands switch the power stage on by themselves
and nobody can read whether it is on, so jog, move and step on servo-can run
only with --enable (exit 2, nothing sent, without it); the stage stays on.
</source>
        <translation>用法：drivedesk-cli [OPTIONS] jog SPEED [--duration S] [--enable]
以 SPEED 点动运行（负值：反方向），直到 --duration 结束、Ctrl-C、SIGTERM
或出现任何错误，然后停止。未给出 --duration 时一直运行到按下 Ctrl-C。
再按一次 Ctrl-C 会发送急停（该系列支持时）。
--enable：servo-can 的运动指令会自行打开功率级（伺服使能），且无法读出其是否
已打开，因此 servo-can 上的 jog、move 和 step 只有加 --enable 才会运行（否则退出码 2，
不发送任何内容）；功率级此后保持打开。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] move (--by N | --to N) [--speed V] [--no-wait] [--enable]
Relative (--by) or absolute (--to) move, in the drive&apos;s position units, at
--speed (the family&apos;s unit). Waits until the axis is at rest again (the link
and its keep-alives stay up meanwhile); --no-wait returns once the drive has
started. Ctrl-C stops the axis. --enable: as for jog (servo-can needs it).
</source>
        <translation>用法：drivedesk-cli [OPTIONS] move (--by N | --to N) [--speed V] [--no-wait] [--enable]
相对（--by）或绝对（--to）定位，单位为驱动器的位置单位，速度为 --speed
（该系列的速度单位）。等待轴重新静止（期间保持连接及保活报文）；
--no-wait 在驱动器开始运动后即返回。Ctrl-C 停止轴。 --enable：同 jog（servo-can 需要）。
</translation>
    </message>
    <message>
        <source>Usage: drivedesk-cli [OPTIONS] step velocity SPEED --duration S --max-speed V --max-travel N
       drivedesk-cli [OPTIONS] step position DISTANCE --speed V --max-travel N [--max-speed V]
       drivedesk-cli [OPTIONS] step reversal SPEED --duration S --max-speed V --max-travel N
          [--max-duration S] [--record S] [--pre 0.1s|25%] [--channels CH,...]
          [--no-return] [--counts-per-rev N] [--enable] [--notes TEXT] [-o RUN.ddrun]
velocity: run at SPEED for S seconds, then stop. position: move by DISTANCE at V.
reversal: run at +SPEED for S seconds, then at -SPEED for S seconds, then stop.
The limits are required (exit 2, nothing sent, without them): --max-speed (the
speed unit; a position step: 1.5 x --speed unless given), --max-travel from the
start position (pulses), --max-duration until the axis is at rest (default: the
step&apos;s time + 2 s; position 10 s). A test whose predicted travel or time (with
its stop; --counts-per-rev for r/min drives, default 10000) does not fit them is
refused, no motion sent. The captured speed and position are watched against
them (the travel early enough to stop inside it); an alarm, a limit, Ctrl-C, a
lost link, or a STOP or command from elsewhere (another master, the drive&apos;s
panel) stops the axis and ends the test with exit code 1; nothing moves after
it, and -o saves the record so far, marked aborted. The capture runs from --pre
(0.05s, or a percentage of the capture) before the motion command for --record
seconds (default: the step&apos;s time + 0.3 s; a position step: until the axis is
at rest, + 0.3 s).
A completed test returns to its start position, announced, under the same
limits and STOP (--no-return: it stays), prints
the metrics with their resolution or why they cannot be resolved, and saves the
run to RUN.ddrun with the tuning parameters read from the drive (docs/tuning.md).
--enable: as for jog (servo-can needs it).
</source>
        <translation>用法：drivedesk-cli [选项] step velocity SPEED --duration S --max-speed V --max-travel N
      drivedesk-cli [选项] step position DISTANCE --speed V --max-travel N [--max-speed V]
      drivedesk-cli [选项] step reversal SPEED --duration S --max-speed V --max-travel N
          [--max-duration S] [--record S] [--pre 0.1s|25%] [--channels CH,...]
          [--no-return] [--counts-per-rev N] [--enable] [--notes TEXT] [-o RUN.ddrun]
velocity：以 SPEED 运行 S 秒后停止。position：以速度 V 相对移动 DISTANCE。
reversal：以 +SPEED 运行 S 秒，再以 -SPEED 运行 S 秒，然后停止。
限值为必填（缺少时退出码 2，不发送任何内容）：--max-speed（速度单位；定位阶跃
未给出时为 --speed 的 1.5 倍）、--max-travel 距起始位置的最大行程（脉冲数）、
--max-duration 到轴静止的最长时间（默认：阶跃时间 + 2 秒；定位 10 秒）。预测的
行程或时间（含停止过程；r/min 驱动器用 --counts-per-rev，默认 10000）超出限值
的测试会被拒绝，不发送任何运动指令。采集到的速度和位置按这些限值监视（行程提前
触发，使轴停在限值以内）；报警、超出限值、Ctrl-C、链路断开，或来自别处的停止
或指令（其他主站、驱动器面板）都会停止轴并以退出码 1 结束测试；此后不再有任何
运动，-o 会保存到此为止的记录并标记为中止。采集从运动指令前 --pre（0.05s，或
占整个采集的百分比）开始，持续 --record 秒（默认：阶跃时间 + 0.3 秒；定位阶跃：
直到轴静止后再加 0.3 秒）。
测试完成后回到起始位置，事先告知，并受同样的限值和 STOP 约束（--no-return：
留在原处），打印
各项指标及其分辨率或无法分辨的原因，并将运行记录连同从驱动器读取的调谐参数
保存到 RUN.ddrun（docs/tuning.md）。
--enable：同 jog（servo-can 需要）。
</translation>
    </message>
    <message>
        <source>--machine needs a name of 1 to 200 characters, e.g. --machine &quot;Press line 3&quot;.</source>
        <translation>--machine 需要 1 到 200 个字符的名称，例如 --machine &quot;Press line 3&quot;。</translation>
    </message>
    <message>
        <source>  --machine NAME                 the machine or project the drives belong to: the
                                 verification journal keeps each machine&apos;s drives
                                 apart (docs/record.md)
</source>
        <translation>  --machine NAME                 驱动器所属的机器或项目：校验日志按机器分开
                                 记录各驱动器（docs/record.md）
</translation>
    </message>
</context>
<context>
    <name>dd::CliCommand</name>
    <message>
        <source>Warning: %1</source>
        <translation>警告：%1</translation>
    </message>
    <message>
        <source>The drive did not identify itself (%1); going on.</source>
        <translation>驱动器未返回标识（%1）；继续执行。</translation>
    </message>
    <message>
        <source>Interrupted.</source>
        <translation>已中断。</translation>
    </message>
    <message>
        <source>The link to the drive was lost. Check the adapter and its cable.</source>
        <translation>与驱动器的连接已断开。请检查转换器及其电缆。</translation>
    </message>
    <message>
        <source>If the address or baud rate may be wrong, try: drivedesk-cli ... scan</source>
        <translation>如果地址或波特率可能有误，请尝试：drivedesk-cli ... scan</translation>
    </message>
    <message>
        <source>&quot;%1&quot; needs %2. See: drivedesk-cli %1 --help</source>
        <translation>“%1”需要%2。参见：drivedesk-cli %1 --help</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: unexpected argument &quot;%2&quot;. See: drivedesk-cli %1 --help</source>
        <translation>“%1”：多余的参数“%2”。参见：drivedesk-cli %1 --help</translation>
    </message>
    <message>
        <source>On %1 drives a motion command switches the power stage on by itself, and whether it is on cannot be read back. Add --enable to allow it: the power stage is then on, and stays on afterwards (the motor holds its position) until `enable off`. Nothing was sent after identifying the drive.</source>
        <translation>在 %1 驱动器上，运动指令会自行打开功率级，且无法读出其是否已打开。加 --enable 表示允许：功率级随即打开，并在之后保持打开（电机保持位置），直到执行 `enable off`。识别驱动器之后未发送任何内容。</translation>
    </message>
    <message>
        <source>--enable: this command switches the power stage on.</source>
        <translation>--enable：此命令会打开功率级。</translation>
    </message>
    <message>
        <source>The power stage may be on (this command was allowed to switch it on) and stays so, the motor holding its position; `enable off` switches it off.</source>
        <translation>功率级可能已打开（此命令被允许打开它）并保持打开，电机保持位置；`enable off` 可将其关闭。</translation>
    </message>
</context>
<context>
    <name>dd::InfoCommand</name>
    <message>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>not readable</source>
        <translation>不可读取</translation>
    </message>
    <message>
        <source>State</source>
        <translation>状态</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Capabilities</source>
        <translation>支持的功能</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>通道</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
</context>
<context>
    <name>dd::ChannelsCommand</name>
    <message>
        <source>Could not identify the drive (%1); listing the family&apos;s channels.</source>
        <translation>无法识别驱动器（%1）；列出该系列的通道。</translation>
    </message>
</context>
<context>
    <name>dd::StopCommand</name>
    <message>
        <source>Emergency stop sent.</source>
        <translation>已发送急停。</translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation>已停止。</translation>
    </message>
</context>
<context>
    <name>dd::EnableCommand</name>
    <message>
        <source>on or off</source>
        <translation>on 或 off</translation>
    </message>
    <message>
        <source>Servo enabled.</source>
        <translation>伺服已使能。</translation>
    </message>
    <message>
        <source>Servo disabled.</source>
        <translation>伺服已关闭使能。</translation>
    </message>
</context>
<context>
    <name>dd::ClearAlarmCommand</name>
    <message>
        <source>Alarm clear sent (this family cannot read the alarm back).</source>
        <translation>已发送报警清除命令（该系列无法回读报警）。</translation>
    </message>
    <message>
        <source>Alarm %1 is still active: its cause persists. Remove the cause (see the drive&apos;s manual), then clear again.</source>
        <translation>报警 %1 仍然存在：报警原因未消除。请先排除原因（参见驱动器手册），再重新清除。</translation>
    </message>
    <message>
        <source>Alarm cleared.</source>
        <translation>报警已清除。</translation>
    </message>
</context>
<context>
    <name>dd::EeCommand</name>
    <message>
        <source>an operation: set, rd, ba, rs or def</source>
        <translation>一个操作：set、rd、ba、rs 或 def</translation>
    </message>
    <message>
        <source>ee: unknown operation &quot;%1&quot;. Operations: set, rd, ba, rs, def.</source>
        <translation>ee：未知操作“%1”。可用操作：set、rd、ba、rs、def。</translation>
    </message>
    <message>
        <source>%1: %2 ...</source>
        <translation>%1：%2 ...</translation>
    </message>
    <message>
        <source>%1 done.</source>
        <translation>%1 已完成。</translation>
    </message>
    <message>
        <source>Waiting for the EEPROM operation to finish (the drive completes it anyway).</source>
        <translation>正在等待 EEPROM 操作完成（驱动器无论如何都会完成该操作）。</translation>
    </message>
    <message>
        <source>EEPROM operations exist only on %1 drives (--family %1).</source>
        <translation>只有 %1 驱动器支持 EEPROM 操作（--family %1）。</translation>
    </message>
</context>
<context>
    <name>dd::MonitorCommand</name>
    <message>
        <source>a comma-separated list of channels, e.g. speed,torque (see the channels command)</source>
        <translation>逗号分隔的通道列表，例如 speed,torque（参见 channels 命令）</translation>
    </message>
    <message>
        <source>monitor: empty channel name in &quot;%1&quot;.</source>
        <translation>monitor：“%1”中有空的通道名称。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2. Check the folder exists and is writable.</source>
        <translation>无法写入 %1：%2。请检查文件夹是否存在且可写。</translation>
    </message>
    <message>
        <source>This drive has no channel %1. Its channels: %2.</source>
        <translation>该驱动器没有通道 %1。它的通道：%2。</translation>
    </message>
    <message>
        <source>time [s]</source>
        <translation>时间 [s]</translation>
    </message>
    <message>
        <source>%1 ticks were skipped because the link was slower than %2 Hz; lower --rate or sample fewer channels.</source>
        <translation>连接速度跟不上 %2 Hz，跳过了 %1 个采样周期；请降低 --rate 或减少采样通道。</translation>
    </message>
    <message>
        <source>%1 samples written to %2.</source>
        <translation>已将 %1 个采样写入 %2。</translation>
    </message>
</context>
<context>
    <name>dd::JogCommand</name>
    <message>
        <source>a speed, e.g. jog 100 or jog -100</source>
        <translation>一个速度，例如 jog 100 或 jog -100</translation>
    </message>
    <message>
        <source>jog speed</source>
        <translation>点动速度</translation>
    </message>
    <message>
        <source>The jog lease ran out and the drive stopped the axis.</source>
        <translation>点动租约已到期，驱动器已停止轴。</translation>
    </message>
    <message>
        <source>The drive raised alarm %1 while jogging; stopped.</source>
        <translation>点动时驱动器发生报警 %1；已停止。</translation>
    </message>
    <message>
        <source>Jogging at %1; press Ctrl-C to stop.</source>
        <translation>正在以 %1 点动；按 Ctrl-C 停止。</translation>
    </message>
    <message>
        <source>Second interrupt: emergency stop.</source>
        <translation>再次中断：急停。</translation>
    </message>
    <message>
        <source>STOP FAILED: %1 The axis may still be moving: use the machine&apos;s emergency stop.</source>
        <translation>停止失败：%1 轴可能仍在运动：请使用机器的急停按钮。</translation>
    </message>
    <message>
        <source>Jogged at %1 for %2 s; stopped (%3).</source>
        <translation>以 %1 点动了 %2 s；已停止（%3）。</translation>
    </message>
    <message>
        <source>duration ended</source>
        <translation>时长已到</translation>
    </message>
    <message>
        <source>interrupted</source>
        <translation>被中断</translation>
    </message>
    <message>
        <source>The link was lost while jogging (%1). The drive&apos;s own watchdog stops the axis where the family has one; check it has stopped.</source>
        <translation>点动时连接中断（%1）。该系列的驱动器若有看门狗，会自行停止轴；请确认轴已停止。</translation>
    </message>
    <message>
        <source>STOP FAILED: %1 The drive&apos;s own watchdog stops the axis when it hears nothing from us; check that it has stopped.</source>
        <translation>停止失败：%1 驱动器收不到本机的通讯时，其自身的看门狗会停止电机；请确认电机已停止。</translation>
    </message>
    <message>
        <source>The link was lost while jogging (%1). %2</source>
        <translation>点动时通讯中断（%1）。%2</translation>
    </message>
</context>
<context>
    <name>dd::PositioningCommand</name>
    <message>
        <source>The drive raised alarm %1 during the motion.</source>
        <translation>运动过程中驱动器发生报警 %1。</translation>
    </message>
    <message>
        <source>Done; position %1.</source>
        <translation>完成；位置 %1。</translation>
    </message>
    <message>
        <source>Interrupted; the axis was stopped.</source>
        <translation>已中断；轴已停止。</translation>
    </message>
    <message>
        <source>The axis is at rest, but the drive does not report where: whether the %1 reached its end is not known.</source>
        <translation>轴已静止，但驱动器未报告位置：无法得知%1是否到达终点。</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>回原点</translation>
    </message>
    <message>
        <source>move</source>
        <translation>定位</translation>
    </message>
    <message>
        <source>Done; the origin was found, position %1.</source>
        <translation>完成；已找到原点，位置 %1。</translation>
    </message>
    <message>
        <source>Something stopped it: a STOP from DriveDesk or another program, the drive&apos;s own inputs or panel, or a limit.</source>
        <translation>有其他原因使其停止：来自 DriveDesk 或其他程序的停止、驱动器自身的输入或面板，或限位。</translation>
    </message>
    <message>
        <source>The move ended at %1, %2 short of the target %3.</source>
        <translation>定位结束于 %1，距目标 %3 还差 %2。</translation>
    </message>
    <message>
        <source>The move ended at %1, %2 beyond the target %3.</source>
        <translation>定位结束于 %1，超过目标 %3 共 %2。</translation>
    </message>
    <message>
        <source>The homing ended at %1 without finding the origin.</source>
        <translation>回原点结束于 %1，未找到原点。</translation>
    </message>
</context>
<context>
    <name>dd::MoveCommand</name>
    <message>
        <source>move needs exactly one of --by N (relative) or --to N (absolute).</source>
        <translation>move 需要且只能给出 --by N（相对）或 --to N（绝对）之一。</translation>
    </message>
    <message>
        <source>Moving by %1.</source>
        <translation>相对运动 %1。</translation>
    </message>
    <message>
        <source>Moving to %1.</source>
        <translation>运动到 %1。</translation>
    </message>
    <message>
        <source>The drive does not report its position: nothing was moved.</source>
        <translation>驱动器未报告其位置：未进行任何运动。</translation>
    </message>
</context>
<context>
    <name>dd::HomeCommand</name>
    <message>
        <source>Homing (%1 direction first).</source>
        <translation>回零（先向%1方向）。</translation>
    </message>
    <message>
        <source>positive</source>
        <translation>正</translation>
    </message>
    <message>
        <source>negative</source>
        <translation>负</translation>
    </message>
</context>
<context>
    <name>dd::GetCommand</name>
    <message>
        <source>one or more parameters, e.g. get PA12 P4 speed-gain</source>
        <translation>一个或多个参数，例如 get PA12 P4 speed-gain</translation>
    </message>
    <message>
        <source>not readable (write-only)</source>
        <translation>不可读取（只写参数）</translation>
    </message>
</context>
<context>
    <name>dd::SetCommand</name>
    <message>
        <source>one or more PARAM=VALUE, e.g. set PA12=300</source>
        <translation>一个或多个 PARAM=VALUE，例如 set PA12=300</translation>
    </message>
    <message>
        <source>set: write PARAM=VALUE, e.g. PA12=300 (got &quot;%1&quot;).</source>
        <translation>set：请写成 PARAM=VALUE，例如 PA12=300（实际为“%1”）。</translation>
    </message>
    <message>
        <source>set: %1 is given twice.</source>
        <translation>set：%1 给出了两次。</translation>
    </message>
    <message>
        <source>not written</source>
        <translation>未写入</translation>
    </message>
    <message>
        <source>NOT WRITTEN: %1</source>
        <translation>未写入：%1</translation>
    </message>
    <message>
        <source>verified</source>
        <translation>已校验</translation>
    </message>
    <message>
        <source>written (write-only: cannot be read back)</source>
        <translation>已写入（只写参数：无法回读）</translation>
    </message>
    <message>
        <source>MISMATCH: read back %1</source>
        <translation>不一致：回读值为 %1</translation>
    </message>
    <message>
        <source>Not every value was verified.</source>
        <translation>并非所有值都已校验通过。</translation>
    </message>
    <message>
        <source>The values are in the drive&apos;s RAM; `ee set` stores them to EEPROM.</source>
        <translation>这些值目前在驱动器的 RAM 中；用 `ee set` 将其存入 EEPROM。</translation>
    </message>
</context>
<context>
    <name>dd::ScanCommand</name>
    <message>
        <source>scan: --from %1 is above --to %2.</source>
        <translation>scan：--from %1 大于 --to %2。</translation>
    </message>
    <message>
        <source>scan: --bauds is for serial links; a CAN bus runs at one bitrate (--bitrate).</source>
        <translation>scan：--bauds 只用于串口连接；CAN 总线只有一个波特率（--bitrate）。</translation>
    </message>
    <message>
        <source>This family cannot scan.</source>
        <translation>该系列不支持扫描。</translation>
    </message>
    <message>
        <source>Scanning addresses %1 to %2</source>
        <translation>正在扫描地址 %1 到 %2</translation>
    </message>
    <message>
        <source> at %1 baud</source>
        <translation>，波特率 %1</translation>
    </message>
    <message>
        <source>No drive answered. Check the wiring (A/B or CANH/CANL swapped?), the termination, the family (--family) and, on a serial bus, try more baud rates with --bauds.</source>
        <translation>没有驱动器应答。请检查接线（A/B 或 CANH/CANL 是否接反？）、终端电阻和驱动器系列（--family）；串口总线上可用 --bauds 尝试更多波特率。</translation>
    </message>
    <message numerus="yes">
        <source>Scan interrupted; %n drive(s) found.</source>
        <translation>
            <numerusform>扫描已中断；找到 %n 台驱动器。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) found.</source>
        <translation>
            <numerusform>找到 %n 台驱动器。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>dd::FamilyTraits</name>
    <message>
        <source>Servo (CAN)</source>
        <translation>伺服（CAN）</translation>
    </message>
    <message>
        <source>CAN</source>
        <translation>CAN</translation>
    </message>
    <message>
        <source>r/min</source>
        <translation>r/min</translation>
    </message>
    <message>
        <source>counts</source>
        <translation>计数</translation>
    </message>
    <message>
        <source>Servo (Modbus)</source>
        <translation>伺服（Modbus）</translation>
    </message>
    <message>
        <source>RTU (binary)</source>
        <translation>RTU（二进制）</translation>
    </message>
    <message>
        <source>Shuoke stepper</source>
        <translation>硕科步进</translation>
    </message>
    <message>
        <source>ASCII</source>
        <translation>ASCII</translation>
    </message>
    <message>
        <source>PLC mode (Modbus registers)</source>
        <translation>PLC 模式（Modbus 寄存器）</translation>
    </message>
    <message>
        <source>pulses/s</source>
        <translation>脉冲/秒</translation>
    </message>
    <message>
        <source>pulses</source>
        <translation>脉冲</translation>
    </message>
</context>
<context>
    <name>dd::WriteVerification</name>
    <message>
        <source>Not readable: the drive cannot report this setting; %1 is kept as the last value written.</source>
        <translation>不可读：驱动器无法报告该设置；保留最后写入的值 %1。</translation>
    </message>
    <message>
        <source>The drive did not take the value: it reads back %1.</source>
        <translation>驱动器未接受该值：回读为 %1。</translation>
    </message>
    <message>
        <source>Wrote %1, but the drive reads back %2.</source>
        <translation>写入 %1，但驱动器回读为 %2。</translation>
    </message>
    <message numerus="yes">
        <source>Written %n time(s).</source>
        <translation>
            <numerusform>已写入 %n 次。</numerusform>
        </translation>
    </message>
    <message>
        <source>The write was not confirmed and could not be read back, so whether the drive took the value is unknown: %1 Read it again.</source>
        <translation>写入未得到确认，也无法回读，驱动器是否接受该值未知：%1 请重新读取。</translation>
    </message>
    <message>
        <source>Written, but it could not be read back: %1</source>
        <translation>已写入，但无法回读：%1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) read back with another value than written (first: %1: %2). The drive may limit the value or not accept it in its present state, or the parameter may be read-only.</source>
        <translation>
            <numerusform>%n 个参数的回读值与写入值不同（第一个：%1：%2）。驱动器可能限制了该值或在当前状态下不接受它，或该参数为只读。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>dd::SerialAccess</name>
    <message>
        <source>You may not use the serial port %1 (permission denied), and no group gives access to it. Ask the administrator of this computer for access.</source>
        <translation>您无权使用串口 %1（权限被拒绝），且没有任何用户组可以访问它。请向这台计算机的管理员申请访问权限。</translation>
    </message>
    <message>
        <source>You may not use the serial port %1 yet: you were added to the group &apos;%2&apos; after you logged in. Log out and log in again (or restart the computer).</source>
        <translation>您暂时还不能使用串口 %1：您是在登录之后才被加入用户组“%2”的。请注销并重新登录（或重启计算机）。</translation>
    </message>
    <message>
        <source>You may not use the serial port %1: it belongs to the group &apos;%2&apos;, and you are not a member. Add yourself once with
    %3
then log out and log in again (or restart the computer).</source>
        <translation>您无权使用串口 %1：它属于用户组“%2”，而您不是该组成员。请执行一次
    %3
把自己加入该组，然后注销并重新登录（或重启计算机）。</translation>
    </message>
</context>
<context>
    <name>dd::SerialAccessDialog</name>
    <message>
        <source>Copied</source>
        <translation>已复制</translation>
    </message>
    <message>
        <source>No permission for %1</source>
        <translation>无权访问 %1</translation>
    </message>
    <message>
        <source>You may not use the serial port %1: it belongs to the group &apos;%2&apos;, and you are not a member. Add yourself once, in a terminal:</source>
        <translation>您无权使用串口 %1：它属于用户组“%2”，而您不是该组成员。请在终端中执行一次下面的命令把自己加入该组：</translation>
    </message>
    <message>
        <source>Then log out and log in again (or restart the computer), so that the new group takes effect, and connect again.</source>
        <translation>然后注销并重新登录（或重启计算机），使新的用户组生效，再重新连接。</translation>
    </message>
    <message>
        <source>&amp;Copy command</source>
        <translation>复制命令(&amp;C)</translation>
    </message>
</context>
<context>
    <name>dd::AboutDialog</name>
    <message>
        <source>About DriveDesk</source>
        <translation>关于 DriveDesk</translation>
    </message>
    <message>
        <source>%1 (built with %2)</source>
        <translation>%1（编译时为 %2）</translation>
    </message>
    <message>
        <source>&lt;h3&gt;DriveDesk %1&lt;/h3&gt;&lt;p&gt;Commissioning and tuning workbench for servo and stepper drives over RS485 / RS232 and CAN.&lt;/p&gt;&lt;p&gt;Drive families: %2.&lt;/p&gt;&lt;p&gt;Qt %3.&lt;/p&gt;&lt;p&gt;DriveDesk is free software: you can redistribute it and modify it under the terms of the GNU General Public License, version 3 or (at your option) any later version. It comes with ABSOLUTELY NO WARRANTY. See the LICENSE file, or &lt;a href=&quot;https://www.gnu.org/licenses/gpl-3.0.html&quot;&gt;gnu.org/licenses/gpl-3.0&lt;/a&gt;.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;DriveDesk %1&lt;/h3&gt;&lt;p&gt;通过 RS485 / RS232 和 CAN 调试和整定伺服与步进驱动器的工作台。&lt;/p&gt;&lt;p&gt;驱动器系列：%2。&lt;/p&gt;&lt;p&gt;Qt %3。&lt;/p&gt;&lt;p&gt;DriveDesk 是自由软件：您可以依据 GNU 通用公共许可证第 3 版或（由您选择）任何更新的版本再发布和修改它。它不提供任何担保。详见 LICENSE 文件或 &lt;a href=&quot;https://www.gnu.org/licenses/gpl-3.0.html&quot;&gt;gnu.org/licenses/gpl-3.0&lt;/a&gt;。&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>dd::CommandLineFile</name>
    <message>
        <source>%1 opens in the drive&apos;s tabs when a drive is selected: connect (File → Connect) or start the demo bench.</source>
        <translation>选中驱动器后，%1 会在该驱动器的标签页中打开：请连接（文件 → 连接）或启动演示试验台。</translation>
    </message>
    <message>
        <source>%1 does not exist.</source>
        <translation>%1 不存在。</translation>
    </message>
    <message>
        <source>%1 is not a file that can be read.</source>
        <translation>%1 不是可读取的文件。</translation>
    </message>
    <message>
        <source>No tab of this drive opens %1; it stays under File → Recent files.</source>
        <translation>这个驱动器的标签页都不能打开 %1；它保留在“文件 → 最近的文件”中。</translation>
    </message>
</context>
<context>
    <name>dd::ParameterComparison</name>
    <message>
        <source>%1 is of a %2 drive and %3 of a %4 drive: parameters of different families have different meanings and are never compared.</source>
        <translation>%1 属于 %2 驱动器，%3 属于 %4 驱动器：不同系列的参数含义不同，从不比较。</translation>
    </message>
</context>
<context>
    <name>dd::ParameterSource</name>
    <message>
        <source>defaults</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
</context>
<context>
    <name>dd::Spectrum</name>
    <message>
        <source>channel %1 is not in the capture (it has %2)</source>
        <translation>采集数据中没有通道 %1（有：%2）</translation>
    </message>
    <message numerus="yes">
        <source>%n gap(s) in the capture were bridged by interpolation</source>
        <translation>
            <numerusform>采集数据中的 %n 处间断已用插值补齐</numerusform>
        </translation>
    </message>
    <message>
        <source>a spectrum needs at least 16 samples over a time span</source>
        <translation>频谱至少需要 16 个跨越一段时间的采样点</translation>
    </message>
    <message>
        <source>the FFT could not be set up for %1 points</source>
        <translation>无法为 %1 个点建立 FFT</translation>
    </message>
    <message>
        <source>Nyquist frequency %1 Hz (half the %2 Hz sample rate): usable band %3–%4 Hz; nothing above %1 Hz can be seen, and what is there folds back below it</source>
        <translation>奈奎斯特频率 %1 Hz（%2 Hz 采样率的一半）：可用频带 %3–%4 Hz；高于 %1 Hz 的成分看不到，而且会折叠回它以下</translation>
    </message>
    <message>
        <source>the peak at %1 Hz may be an alias: the samples, at their own times, fit %2 Hz (above the Nyquist frequency) as well or better; capture at a higher rate before placing a notch</source>
        <translation>%1 Hz 处的峰可能是混叠：按各自的采样时刻，这些样本与 %2 Hz（高于奈奎斯特频率）拟合得一样好或更好；设置陷波器之前请用更高的采样率采集</translation>
    </message>
    <message>
        <source>the peak at %1 Hz is within 10 % of the Nyquist frequency: its frequency is not reliable, it may be an alias</source>
        <translation>%1 Hz 处的峰距奈奎斯特频率不到 10 %：其频率不可靠，可能是混叠</translation>
    </message>
</context>
<context>
    <name>dd::StepMetrics</name>
    <message>
        <source>channel %1 was not captured</source>
        <translation>未采集通道 %1</translation>
    </message>
    <message>
        <source>channel %1 has no values</source>
        <translation>通道 %1 没有数值</translation>
    </message>
    <message>
        <source>fewer than two samples</source>
        <translation>采样点少于两个</translation>
    </message>
    <message>
        <source>the response channel %1 was not captured</source>
        <translation>未采集响应通道 %1</translation>
    </message>
    <message>
        <source>fewer than four samples in the step</source>
        <translation>阶跃内的采样点少于四个</translation>
    </message>
    <message>
        <source>no step: the target equals the starting value</source>
        <translation>没有阶跃：目标值等于起始值</translation>
    </message>
    <message>
        <source>the response never reached 90 % of the step</source>
        <translation>响应从未达到阶跃的 90 %</translation>
    </message>
    <message>
        <source>the rise is shorter than two sample intervals (%1 ms): not resolvable at this sample rate</source>
        <translation>上升时间短于两个采样间隔（%1 ms）：此采样率下无法分辨</translation>
    </message>
    <message>
        <source>the response did not settle within ±%1 % in the record</source>
        <translation>记录中响应未稳定在 ±%1 % 以内</translation>
    </message>
    <message>
        <source>settles within two sample intervals (%1 ms): not resolvable at this sample rate</source>
        <translation>在两个采样间隔（%1 ms）内即稳定：此采样率下无法分辨</translation>
    </message>
    <message>
        <source>metrics.%1 is missing</source>
        <translation>缺少 metrics.%1</translation>
    </message>
    <message>
        <source>resolution.%1 must be a number ≥ 0</source>
        <translation>resolution.%1 必须是 ≥ 0 的数字</translation>
    </message>
    <message>
        <source>metrics.%1 must be a number or null</source>
        <translation>metrics.%1 必须是数字或 null</translation>
    </message>
    <message>
        <source>metrics.%1 is not a known metric</source>
        <translation>metrics.%1 不是已知的指标</translation>
    </message>
</context>
<context>
    <name>dd::TriggerSpec</name>
    <message>
        <source>Unknown trigger &quot;%1&quot;: use %2.</source>
        <translation>未知触发条件“%1”：请使用 %2。</translation>
    </message>
    <message>
        <source>The trigger &quot;%1&quot; takes no channel or level.</source>
        <translation>触发条件“%1”不带通道或电平。</translation>
    </message>
    <message>
        <source>The trigger &quot;%1&quot; needs a channel and a level, e.g. %2:speed:500.</source>
        <translation>触发条件“%1”需要通道和电平，例如 %2:speed:500。</translation>
    </message>
    <message>
        <source>The trigger level &quot;%1&quot; is not a number.</source>
        <translation>触发电平“%1”不是数字。</translation>
    </message>
</context>
<context>
    <name>dd::TuningRun</name>
    <message>
        <source>%1 must be an object</source>
        <translation>%1 必须是对象</translation>
    </message>
    <message>
        <source>%1 must be a string</source>
        <translation>%1 必须是字符串</translation>
    </message>
    <message>
        <source>%1 must be a number</source>
        <translation>%1 必须是数字</translation>
    </message>
    <message>
        <source>%1 = %2 is outside %3 to %4</source>
        <translation>%1 = %2 超出范围 %3 到 %4</translation>
    </message>
    <message>
        <source>%1 must be a whole number</source>
        <translation>%1 必须是整数</translation>
    </message>
    <message>
        <source>%1 is not valid JSON: %2 at byte %3</source>
        <translation>%1 不是有效的 JSON：%2（第 %3 字节）</translation>
    </message>
    <message>
        <source>%1: the top level must be an object</source>
        <translation>%1：顶层必须是对象</translation>
    </message>
    <message>
        <source>%1: unknown field &quot;%2&quot;</source>
        <translation>%1：未知字段“%2”</translation>
    </message>
    <message>
        <source>%1 is not a DriveDesk run file (format must be &quot;%2&quot;)</source>
        <translation>%1 不是 DriveDesk 运行记录文件（format 必须为“%2”）</translation>
    </message>
    <message>
        <source>%1: run format version %2 is not supported (this DriveDesk reads %3)</source>
        <translation>%1：不支持运行记录格式版本 %2（本版 DriveDesk 读取 %3）</translation>
    </message>
    <message>
        <source>%1: created &quot;%2&quot; is not an ISO 8601 time</source>
        <translation>%1：created “%2”不是 ISO 8601 时间</translation>
    </message>
    <message>
        <source>%1: drive.family &quot;%2&quot; is not a known family (%3)</source>
        <translation>%1：drive.family“%2”不是已知的驱动器系列（%3）</translation>
    </message>
    <message>
        <source>%1: test.type &quot;%2&quot; is not one of %3</source>
        <translation>%1：test.type“%2”不是 %3 之一</translation>
    </message>
    <message>
        <source>%1: test.parameters must be an object</source>
        <translation>%1：test.parameters 必须是对象</translation>
    </message>
    <message>
        <source>%1: trigger.mode &quot;%2&quot; is not single, normal or auto</source>
        <translation>%1：trigger.mode“%2”不是 single、normal 或 auto</translation>
    </message>
    <message>
        <source>%1: channels must be a non-empty array</source>
        <translation>%1：channels 必须是非空数组</translation>
    </message>
    <message>
        <source>%1: each channel must be an object</source>
        <translation>%1：每个通道都必须是对象</translation>
    </message>
    <message>
        <source>%1: channel id &quot;%2&quot; is empty, &quot;time&quot; or repeated</source>
        <translation>%1：通道 id“%2”为空、为“time”或重复</translation>
    </message>
    <message>
        <source>%1: samples.%2 is not a listed channel</source>
        <translation>%1：samples.%2 不是列出的通道</translation>
    </message>
    <message>
        <source>%1: samples.time must be an array</source>
        <translation>%1：samples.time 必须是数组</translation>
    </message>
    <message>
        <source>%1: samples.time[%2] must be a number</source>
        <translation>%1：samples.time[%2] 必须是数字</translation>
    </message>
    <message>
        <source>%1: samples.time[%2] goes back in time</source>
        <translation>%1：samples.time[%2] 时间倒退</translation>
    </message>
    <message>
        <source>%1: trigger.preTriggerSamples is %2 but %3 samples are before the trigger</source>
        <translation>%1：trigger.preTriggerSamples 为 %2，但触发前有 %3 个采样点</translation>
    </message>
    <message>
        <source>%1: samples.%2 must be an array of %3 values, like samples.time</source>
        <translation>%1：samples.%2 必须是含 %3 个值的数组，与 samples.time 相同</translation>
    </message>
    <message>
        <source>%1: samples.%2[%3] must be a number or null</source>
        <translation>%1：samples.%2[%3] 必须是数字或 null</translation>
    </message>
    <message>
        <source>%1: metricsChannel &quot;%2&quot; is not a listed channel</source>
        <translation>%1：metricsChannel“%2”不是列出的通道</translation>
    </message>
    <message>
        <source>%1: metricNotes must be strings</source>
        <translation>%1：metricNotes 必须是字符串</translation>
    </message>
    <message>
        <source>%1: metricNotes must be an array of strings</source>
        <translation>%1：metricNotes 必须是字符串数组</translation>
    </message>
    <message>
        <source>%1: resolution must be an object</source>
        <translation>%1：resolution 必须是对象</translation>
    </message>
    <message>
        <source>%1: tuning must be an array</source>
        <translation>%1：tuning 必须是数组</translation>
    </message>
    <message>
        <source>%1: each tuning entry must be an object</source>
        <translation>%1：每个 tuning 条目都必须是对象</translation>
    </message>
    <message>
        <source>%1: tuning role &quot;%2&quot; is unknown</source>
        <translation>%1：tuning 用途“%2”未知</translation>
    </message>
    <message>
        <source>%1: tuning lists %2 twice</source>
        <translation>%1：tuning 中 %2 出现了两次</translation>
    </message>
    <message>
        <source>%1: gaps must be an array</source>
        <translation>%1：gaps 必须是数组</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Cannot open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB: not a run file</source>
        <translation>%1 大于 %2 MiB：不是运行记录文件</translation>
    </message>
    <message>
        <source>%1: formatVersion must be a number (%2), not %3</source>
        <translation>%1：formatVersion 必须是数字（%2），而不是 %3</translation>
    </message>
    <message>
        <source>%1: samples.time holds %2 samples, more than the %3 a run file may hold</source>
        <translation>%1：samples.time 含 %2 个采样，超过运行记录文件允许的 %3 个</translation>
    </message>
    <message>
        <source>%1: result must be an object</source>
        <translation>%1：result 必须是对象</translation>
    </message>
    <message>
        <source>%1: result.outcome &quot;%2&quot; is not completed or aborted</source>
        <translation>%1：result.outcome“%2”既不是 completed 也不是 aborted</translation>
    </message>
</context>
<context>
    <name>dd::RecordHeader</name>
    <message>
        <source>The header file %1 does not exist.</source>
        <translation>表头文件 %1 不存在。</translation>
    </message>
    <message>
        <source>%1 is a folder, not a header file.</source>
        <translation>%1 是文件夹，不是表头文件。</translation>
    </message>
    <message>
        <source>The header file %1 is %2 bytes; a header file is at most %3 bytes.</source>
        <translation>表头文件 %1 有 %2 字节；表头文件最多 %3 字节。</translation>
    </message>
    <message>
        <source>Cannot read the header file %1: %2</source>
        <translation>无法读取表头文件 %1：%2</translation>
    </message>
    <message>
        <source>%1: a header file is at most %2 bytes.</source>
        <translation>%1：表头文件最多 %2 字节。</translation>
    </message>
    <message>
        <source>%1 is not valid JSON (at byte %2: %3).</source>
        <translation>%1 不是有效的 JSON（第 %2 字节：%3）。</translation>
    </message>
    <message>
        <source>%1: a header file is one JSON object, e.g. {&quot;machine&quot;: &quot;Press 3&quot;, &quot;engineer&quot;: &quot;Li Wei&quot;}.</source>
        <translation>%1：表头文件是一个 JSON 对象，例如 {&quot;machine&quot;: &quot;Press 3&quot;, &quot;engineer&quot;: &quot;Li Wei&quot;}。</translation>
    </message>
    <message>
        <source>%1: unknown field &quot;%2&quot;; a header has the fields %3.</source>
        <translation>%1：未知字段 &quot;%2&quot;；表头的字段为 %3。</translation>
    </message>
    <message>
        <source>%1: the field &quot;%2&quot; must be text (a JSON string).</source>
        <translation>%1：字段 &quot;%2&quot; 必须是文本（JSON 字符串）。</translation>
    </message>
    <message>
        <source>%1: the field &quot;%2&quot; is %3 characters long; at most %4 are allowed.</source>
        <translation>%1：字段 &quot;%2&quot; 长 %3 个字符；最多允许 %4 个。</translation>
    </message>
    <message>
        <source>%1: the field &quot;%2&quot; holds a control character (U+%3).</source>
        <translation>%1：字段 &quot;%2&quot; 含有控制字符（U+%3）。</translation>
    </message>
</context>
<context>
    <name>dd::RecordRenderer</name>
    <message>
        <source>%1 at address %2</source>
        <translation>%1，地址 %2</translation>
    </message>
    <message>
        <source>restore</source>
        <translation>恢复</translation>
    </message>
    <message>
        <source>parameter write</source>
        <translation>参数写入</translation>
    </message>
    <message>
        <source>VERIFICATION FAILED: %1 — the last %2 (%3): %4 of %5 parameter(s) not verified.</source>
        <translation>校验失败：%1 — 最近一次%2（%3）：%5 个参数中有 %4 个未通过校验。</translation>
    </message>
    <message>
        <source>Commissioning record</source>
        <translation>调试记录</translation>
    </message>
    <message>
        <source>Machine / project</source>
        <translation>机器 / 项目</translation>
    </message>
    <message>
        <source>Customer</source>
        <translation>客户</translation>
    </message>
    <message>
        <source>Site</source>
        <translation>现场</translation>
    </message>
    <message>
        <source>Engineer</source>
        <translation>工程师</translation>
    </message>
    <message>
        <source>Date and time</source>
        <translation>日期和时间</translation>
    </message>
    <message>
        <source>DriveDesk version</source>
        <translation>DriveDesk 版本</translation>
    </message>
    <message>
        <source>Computer</source>
        <translation>计算机</translation>
    </message>
    <message>
        <source>Record file (JSON) SHA-256</source>
        <translation>记录文件（JSON）SHA-256</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message numerus="yes">
        <source>Drives (%n)</source>
        <translation>
            <numerusform>驱动器（%n 台）</numerusform>
        </translation>
    </message>
    <message>
        <source>No drive is in this record.</source>
        <translation>此记录中没有驱动器。</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <source>Firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>Link</source>
        <translation>链路</translation>
    </message>
    <message>
        <source>Changed</source>
        <translation>已修改</translation>
    </message>
    <message>
        <source>Verification</source>
        <translation>校验</translation>
    </message>
    <message>
        <source>Alarms</source>
        <translation>报警</translation>
    </message>
    <message>
        <source>none recorded</source>
        <translation>无记录</translation>
    </message>
    <message>
        <source>verified</source>
        <translation>已校验</translation>
    </message>
    <message>
        <source>FAILED (%1)</source>
        <translation>失败（%1）</translation>
    </message>
    <message>
        <source>Drive %1 of %2: %3</source>
        <translation>驱动器 %1/%2：%3</translation>
    </message>
    <message>
        <source>Family</source>
        <translation>系列</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>Link settings</source>
        <translation>链路设置</translation>
    </message>
    <message>
        <source>Parameters not (all) read: %1</source>
        <translation>参数未能（全部）读取：%1</translation>
    </message>
    <message numerus="yes">
        <source>Parameters that differ from the defaults (%n)</source>
        <translation>
            <numerusform>与默认值不同的参数（%n 个）</numerusform>
        </translation>
    </message>
    <message>
        <source>No parameter read differs from its default.</source>
        <translation>读取的参数均与默认值相同。</translation>
    </message>
    <message>
        <source>Index</source>
        <translation>编号</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>默认值</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Every parameter with its value and default is listed in the appendix.</source>
        <translation>附录中列出每个参数及其值和默认值。</translation>
    </message>
    <message>
        <source>Last verification</source>
        <translation>最近一次校验</translation>
    </message>
    <message>
        <source>No restore or parameter write of this drive is recorded.</source>
        <translation>没有此驱动器的恢复或参数写入记录。</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>恢复</translation>
    </message>
    <message>
        <source>Parameter write</source>
        <translation>参数写入</translation>
    </message>
    <message>
        <source>%1 on %2: </source>
        <translation>%1，%2：</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) written and verified.</source>
        <translation>
            <numerusform>%n 个参数已写入并校验。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 parameter(s) NOT verified.</source>
        <translation>%2 个参数中有 %1 个未通过校验。</translation>
    </message>
    <message>
        <source>From the backup file %1, checksum</source>
        <translation>来自备份文件 %1，校验和</translation>
    </message>
    <message>
        <source>Written</source>
        <translation>写入值</translation>
    </message>
    <message>
        <source>Read back</source>
        <translation>回读值</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>No alarm was recorded.</source>
        <translation>没有报警记录。</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>代码</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <source>Seen</source>
        <translation>情况</translation>
    </message>
    <message>
        <source>active when the record was made</source>
        <translation>生成记录时仍存在</translation>
    </message>
    <message>
        <source>cleared</source>
        <translation>已清除</translation>
    </message>
    <message>
        <source>in the session</source>
        <translation>本次会话中出现</translation>
    </message>
    <message>
        <source>Link health</source>
        <translation>链路状况</translation>
    </message>
    <message>
        <source>Not measured.</source>
        <translation>未统计。</translation>
    </message>
    <message numerus="yes">
        <source>Tuning runs (%n)</source>
        <translation>
            <numerusform>调试运行（%n 次）</numerusform>
        </translation>
    </message>
    <message>
        <source>Metric</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>Parameters during the run</source>
        <translation>运行时的参数</translation>
    </message>
    <message>
        <source>Backup files</source>
        <translation>备份文件</translation>
    </message>
    <message>
        <source>No backup file of this drive is recorded.</source>
        <translation>没有此驱动器的备份文件记录。</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>用途</translation>
    </message>
    <message>
        <source>File</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>Checksum</source>
        <translation>校验和</translation>
    </message>
    <message>
        <source>restored onto the drive</source>
        <translation>已恢复到驱动器</translation>
    </message>
    <message>
        <source>saved from the drive</source>
        <translation>从驱动器保存</translation>
    </message>
    <message>
        <source>Appendix %1: every parameter of %2</source>
        <translation>附录 %1：%2 的全部参数</translation>
    </message>
    <message>
        <source>No parameter was read.</source>
        <translation>没有读取到参数。</translation>
    </message>
    <message>
        <source>DriveDesk commissioning record</source>
        <translation>DriveDesk 调试记录</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>第 %1 页，共 %2 页</translation>
    </message>
    <message>
        <source>Record file (JSON) SHA-256: %1</source>
        <translation>记录文件（JSON）SHA-256：%1</translation>
    </message>
    <message>
        <source>Could not draw the record&apos;s pages.</source>
        <translation>无法绘制记录的页面。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>%1 (%2 not compared)</source>
        <translation>%1（%2 个未比较）</translation>
    </message>
    <message numerus="yes">
        <source>Not compared: the dictionary gives no factory default for any of the %n parameter(s) read, so this record cannot say which of them were changed.</source>
        <translation>
            <numerusform>未比较：字典没有为已读取的 %n 个参数中的任何一个给出出厂默认值，因此本记录无法说明其中哪些被修改过。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) not compared: the dictionary gives no factory default for them (shown as “—” in the Default column of the appendix).</source>
        <translation>
            <numerusform>%n 个参数未比较：字典没有给出它们的出厂默认值（附录的“默认值”列中显示为“—”）。</numerusform>
        </translation>
    </message>
    <message>
        <source>The protocol documents of this drive family list no factory defaults for these parameters. A dictionary with the drive&apos;s factory settings (drivedesk-cli --dictionary, or the user dictionary of the family) makes the comparison complete.</source>
        <translation>该驱动器系列的协议文档没有列出这些参数的出厂默认值。使用包含驱动器出厂设置的字典（drivedesk-cli --dictionary，或该系列的用户字典）即可完成比较。</translation>
    </message>
    <message>
        <source>turnaround %1 / %2 / %3 ms (min / median / max)</source>
        <translation>往返时间 %1 / %2 / %3 ms（最小 / 中位 / 最大）</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>无应答</translation>
    </message>
    <message>
        <source>%1: %2 request(s), %3 answered, %4; %5 timeout(s), %6 checksum error(s), %7 late or duplicated reply(ies), %8 retries, %9 failed operation(s).</source>
        <translation>%1：%2 次请求，%3 次应答，%4；%5 次超时，%6 次校验错误，%7 次迟到或重复的应答，%8 次重试，%9 次操作失败。</translation>
    </message>
    <message numerus="yes">
        <source>%n sample(s), one every %1 ms on average</source>
        <translation>
            <numerusform>%n 个采样，平均每 %1 ms 一个</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n gap(s) in the sampling, the longest %1 ms (the plot breaks its lines at those it can show)</source>
        <translation>
            <numerusform>采样中有 %n 处间断，最长 %1 ms（曲线在能显示出的间断处断开）</numerusform>
        </translation>
    </message>
    <message>
        <source>Run file %1, checksum</source>
        <translation>运行文件 %1，校验和</translation>
    </message>
    <message>
        <source>not measured: %1</source>
        <translation>未测得：%1</translation>
    </message>
    <message numerus="yes">
        <source>%n request(s) went out on a line that was never quiet: another master on the bus, or a drive sending on its own.</source>
        <translation>
            <numerusform>%n 个请求是在一直不静默的线路上发出的：总线上有另一个主站，或有驱动器在自行发送。</numerusform>
        </translation>
    </message>
    <message>
        <source>Journal identity</source>
        <translation>日志识别依据</translation>
    </message>
    <message>
        <source>Last EEPROM operation: %1 on %2:</source>
        <translation>最近一次 EEPROM 操作：%1（%2）：</translation>
    </message>
    <message>
        <source>done.</source>
        <translation>已完成。</translation>
    </message>
    <message>
        <source>FAILED: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <source>%1 parameter(s) written and verified, %2 written (not read back: write-only).</source>
        <translation>%1 个参数已写入并校验，%2 个已写入（未回读：只写参数）。</translation>
    </message>
    <message>
        <source>written (not read back: write-only)</source>
        <translation>已写入（未回读：只写参数）</translation>
    </message>
</context>
<context>
    <name>dd::VerificationJournal</name>
    <message>
        <source>Cannot create the folder %1 for the verification journal.</source>
        <translation>无法为校验日志创建文件夹 %1。</translation>
    </message>
    <message>
        <source>Cannot write the verification journal %1: %2</source>
        <translation>无法写入校验日志 %1：%2</translation>
    </message>
    <message>
        <source>not attempted: the restore stopped before this parameter</source>
        <translation>未尝试：恢复在此参数之前已停止</translation>
    </message>
    <message>
        <source>The verification journal %1 is damaged (%2): it is left as it is and its history is not used.</source>
        <translation>校验日志 %1 已损坏（%2）：文件保持原样，其中的历史不予采用。</translation>
    </message>
    <message numerus="yes">
        <source>larger than %n MiB</source>
        <translation>
            <numerusform>大于 %n MiB</numerusform>
        </translation>
    </message>
    <message>
        <source>not JSON at byte %1: %2</source>
        <translation>第 %1 字节处不是 JSON：%2</translation>
    </message>
    <message>
        <source>not a drivedesk-journal</source>
        <translation>不是 drivedesk-journal 文件</translation>
    </message>
    <message>
        <source>it names another drive</source>
        <translation>它属于另一台驱动器</translation>
    </message>
    <message>
        <source>The verification journal %1 is locked by another DriveDesk process (%2); nothing was noted in it.</source>
        <translation>校验日志 %1 被另一个 DriveDesk 进程锁定（%2）；未记入任何内容。</translation>
    </message>
    <message numerus="yes">
        <source>still busy after %n s</source>
        <translation>
            <numerusform>%n 秒后仍被占用</numerusform>
        </translation>
    </message>
    <message>
        <source>the lock file cannot be made</source>
        <translation>无法创建锁文件</translation>
    </message>
</context>
<context>
    <name>dd::CaptureCommand</name>
    <message>
        <source>--%1 must be a number from %2 to %3, not &quot;%4&quot;.</source>
        <translation>--%1 必须是 %2 到 %3 之间的数字，而不是“%4”。</translation>
    </message>
    <message>
        <source>CHANNEL,...</source>
        <translation>CHANNEL,...</translation>
    </message>
    <message>
        <source>Name at least one channel, e.g. speed,current.</source>
        <translation>请至少指定一个通道，例如 speed,current。</translation>
    </message>
    <message>
        <source>The motion trigger belongs to step tests: use drivedesk-cli step.</source>
        <translation>运动触发属于阶跃测试：请使用 drivedesk-cli step。</translation>
    </message>
    <message>
        <source>The trigger channel %1 must be one of the captured channels (%2).</source>
        <translation>触发通道 %1 必须是采集的通道之一（%2）。</translation>
    </message>
    <message>
        <source>--mode must be single or auto, not &quot;%1&quot;.</source>
        <translation>--mode 必须是 single 或 auto，而不是“%1”。</translation>
    </message>
    <message>
        <source>Name the run file: -o RUN.ddrun.</source>
        <translation>请指定运行记录文件：-o RUN.ddrun。</translation>
    </message>
    <message>
        <source>This drive has no channel %1 (it has %2).</source>
        <translation>该驱动器没有通道 %1（有：%2）。</translation>
    </message>
    <message>
        <source>Armed: waiting for the trigger %1.</source>
        <translation>已就绪：等待触发条件 %1。</translation>
    </message>
    <message>
        <source>Capture cancelled before the trigger came.</source>
        <translation>触发前已取消采集。</translation>
    </message>
    <message>
        <source>%1: %2 samples (%3 before the trigger), trigger %4, interval %5 ms (%6 Hz), %7 gap(s), %8 tuning parameter(s)</source>
        <translation>%1：%2 个采样点（触发前 %3 个），触发 %4，间隔 %5 ms（%6 Hz），%7 处间断，%8 个整定参数</translation>
    </message>
</context>
<context>
    <name>dd::FleetBackupCommand</name>
    <message>
        <source>backup of several drives needs the folder to write to: backup --all -o DIR.</source>
        <translation>备份多台驱动器需要指定写入的文件夹：backup --all -o DIR。</translation>
    </message>
    <message>
        <source>backup: %1 is a file; several drives are saved into a folder (-o DIR).</source>
        <translation>backup：%1 是文件；多台驱动器的备份保存在文件夹中（-o DIR）。</translation>
    </message>
    <message>
        <source>backup: the folder %1 does not exist.</source>
        <translation>backup：文件夹 %1 不存在。</translation>
    </message>
    <message>
        <source>backup: cannot create the folder %1.</source>
        <translation>backup：无法创建文件夹 %1。</translation>
    </message>
    <message>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) -&gt; %1</source>
        <translation>
            <numerusform>%n 个参数 -&gt; %1</numerusform>
        </translation>
    </message>
    <message>
        <source>backup: cannot write %1: %2</source>
        <translation>backup：无法写入 %1：%2</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n drive(s) saved to %2 (index: %3).</source>
        <translation>
            <numerusform>%n 台驱动器中有 %1 台已保存到 %2（索引：%3）。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>dd::FleetCommand</name>
    <message>
        <source>%1: give either --all or --address, not both.</source>
        <translation>%1：请给出 --all 或 --address，不能同时给出。</translation>
    </message>
    <message>
        <source>%1: --from and --to narrow the scan of --all.</source>
        <translation>%1：--from 和 --to 用于缩小 --all 的扫描范围。</translation>
    </message>
    <message>
        <source>%1: --from %2 is above --to %3.</source>
        <translation>%1：--from %2 大于 --to %3。</translation>
    </message>
    <message>
        <source>This family cannot scan; name the drives with --address.</source>
        <translation>该系列不能扫描；请用 --address 指定驱动器。</translation>
    </message>
    <message>
        <source>Scanning addresses %1 to %2 ...</source>
        <translation>正在扫描地址 %1 到 %2 ...</translation>
    </message>
    <message>
        <source>Interrupted during the scan; nothing was done.</source>
        <translation>扫描时被中断；未做任何操作。</translation>
    </message>
    <message>
        <source>No drive answered the scan of addresses %1 to %2.</source>
        <translation>扫描地址 %1 到 %2 时没有驱动器应答。</translation>
    </message>
    <message numerus="yes">
        <source>Found %n drive(s): %1.</source>
        <translation>
            <numerusform>找到 %n 台驱动器：%1。</numerusform>
        </translation>
    </message>
    <message>
        <source>Finishing the drives under way so that their reports are complete; no further drive is started.</source>
        <translation>正在完成进行中的驱动器，以便报告完整；不再开始新的驱动器。</translation>
    </message>
    <message>
        <source>The link was lost. Check the adapter and its cable.</source>
        <translation>连接已断开。请检查适配器及其电缆。</translation>
    </message>
    <message>
        <source>drive %1: not attempted (%2)</source>
        <translation>驱动器 %1：未尝试（%2）</translation>
    </message>
    <message>
        <source>drive %1: not attempted</source>
        <translation>驱动器 %1：未尝试</translation>
    </message>
    <message>
        <source>while identifying it</source>
        <translation>识别时</translation>
    </message>
    <message>
        <source>while reading its parameters</source>
        <translation>读取参数时</translation>
    </message>
    <message>
        <source>while writing</source>
        <translation>写入时</translation>
    </message>
    <message>
        <source>before it started</source>
        <translation>开始之前</translation>
    </message>
    <message>
        <source>drive %1: FAILED %2: %3</source>
        <translation>驱动器 %1：%2失败：%3</translation>
    </message>
    <message numerus="yes">
        <source>%n of %1 drive(s) did not complete: %2.</source>
        <translation>
            <numerusform>%1 台驱动器中有 %n 台未完成：%2。</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>dd::FleetRestoreCommand</name>
    <message>
        <source>a backup file</source>
        <translation>一个备份文件</translation>
    </message>
    <message>
        <source>drive %1: already matches the file; nothing to write.</source>
        <translation>驱动器 %1：已与文件一致；无需写入。</translation>
    </message>
    <message numerus="yes">
        <source>drive %1: %n parameter(s) would be written.</source>
        <translation>
            <numerusform>驱动器 %1：将写入 %n 个参数。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>drive %1: %n parameter(s) written and verified.</source>
        <translation>
            <numerusform>驱动器 %1：已写入并校验 %n 个参数。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Dry run on %n drive(s); nothing was sent.</source>
        <translation>
            <numerusform>对 %n 台驱动器试运行；未发送任何内容。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n drive(s) restored from %2.</source>
        <translation>
            <numerusform>%n 台驱动器中有 %1 台已从 %2 恢复。</numerusform>
        </translation>
    </message>
    <message>
        <source>restore %1: a backup folder names its drives; --from and --to do not apply.</source>
        <translation>restore %1：备份文件夹已列明其驱动器；--from 和 --to 不适用。</translation>
    </message>
    <message>
        <source>restore %1: the folder has no index.json (write one with backup --all -o %1): %2</source>
        <translation>restore %1：该文件夹中没有 index.json（可用 backup --all -o %1 生成）：%2</translation>
    </message>
    <message>
        <source>restore %1: %2 is not the index of a backup folder (format &quot;%3&quot;).</source>
        <translation>restore %1：%2 不是备份文件夹的索引（格式应为“%3”）。</translation>
    </message>
    <message>
        <source>restore %1: index format version %2 is not supported (this DriveDesk reads 1).</source>
        <translation>restore %1：不支持索引格式版本 %2（本 DriveDesk 读取版本 1）。</translation>
    </message>
    <message>
        <source>restore %1: the folder holds backups of %2 drives; this link is for %3 drives.</source>
        <translation>restore %1：该文件夹保存的是 %2 驱动器的备份；此链路用于 %3 驱动器。</translation>
    </message>
    <message>
        <source>restore %1: index.json lists a drive without a valid address or file name.</source>
        <translation>restore %1：index.json 中有驱动器缺少有效的地址或文件名。</translation>
    </message>
    <message>
        <source>restore %1: index.json lists no drive.</source>
        <translation>restore %1：index.json 中没有列出驱动器。</translation>
    </message>
    <message>
        <source>restore %1: drive %2 is not in the folder&apos;s index.</source>
        <translation>restore %1：驱动器 %2 不在该文件夹的索引中。</translation>
    </message>
    <message>
        <source>restore %1: drive %2 has no file in the folder (its backup failed). Restore the others with --address %3.</source>
        <translation>restore %1：驱动器 %2 在该文件夹中没有文件（其备份失败）。可用 --address %3 恢复其余驱动器。</translation>
    </message>
    <message>
        <source>restore %1: %2 is the backup of the drive at address %3, but the index gives it to address %4.</source>
        <translation>restore %1：%2 是地址 %3 驱动器的备份，但索引将其分配给地址 %4。</translation>
    </message>
</context>
<context>
    <name>dd::PingCommand</name>
    <message>
        <source>The drive at address %1 answered none of %2 requests. Last error: %3</source>
        <translation>地址 %1 的驱动器对 %2 个请求均未应答。最后一个错误：%3</translation>
    </message>
    <message>
        <source>Answered</source>
        <translation>已应答</translation>
    </message>
    <message>
        <source>%1 of %2 (%3 requests on the wire)</source>
        <translation>%2 个中的 %1 个（线路上共 %3 个请求）</translation>
    </message>
    <message>
        <source>Turnaround</source>
        <translation>往返时间</translation>
    </message>
    <message>
        <source>min %1 ms, median %2 ms, max %3 ms</source>
        <translation>最小 %1 毫秒，中位数 %2 毫秒，最大 %3 毫秒</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>超时</translation>
    </message>
    <message>
        <source>Checksum errors</source>
        <translation>校验错误</translation>
    </message>
    <message>
        <source>Late or duplicated replies</source>
        <translation>迟到或重复的应答</translation>
    </message>
    <message>
        <source>Retries</source>
        <translation>重试</translation>
    </message>
    <message>
        <source>Recommended timeout</source>
        <translation>建议超时</translation>
    </message>
    <message>
        <source>--timeout %1 (reply allowance beyond the wire time, ms)</source>
        <translation>--timeout %1（线路传输时间之外的应答余量，毫秒）</translation>
    </message>
    <message>
        <source>Recommended gap</source>
        <translation>建议间隔</translation>
    </message>
    <message>
        <source>%1 ms between requests</source>
        <translation>请求之间 %1 毫秒</translation>
    </message>
    <message>
        <source>Sent on a busy line</source>
        <translation>在繁忙线路上发送</translation>
    </message>
    <message>
        <source>%1 (the line was never quiet: is another master on the bus, or a drive sending on its own?)</source>
        <translation>%1（线路一直不静默：总线上是否有另一个主站，或有驱动器在自行发送？）</translation>
    </message>
</context>
<context>
    <name>dd::ReportCommand</name>
    <message>
        <source>report %1: %2 is a folder; give a file name.</source>
        <translation>report %1：%2 是文件夹；请给出文件名。</translation>
    </message>
    <message>
        <source>report %1: the folder %2 does not exist.</source>
        <translation>report %1：文件夹 %2 不存在。</translation>
    </message>
    <message>
        <source>report %1: %2 should end in .%3.</source>
        <translation>report %1：%2 应以 .%3 结尾。</translation>
    </message>
    <message>
        <source>report needs the PDF file to write: report -o RECORD.pdf.</source>
        <translation>report 需要要写入的 PDF 文件：report -o RECORD.pdf。</translation>
    </message>
    <message>
        <source>report: the PDF and the JSON file must be two different files.</source>
        <translation>report：PDF 与 JSON 必须是两个不同的文件。</translation>
    </message>
    <message>
        <source>report --header: %1</source>
        <translation>report --header：%1</translation>
    </message>
    <message>
        <source>report --page-size: &quot;%1&quot; is not a page size; use a4 or letter.</source>
        <translation>report --page-size：&quot;%1&quot; 不是纸张尺寸；请用 a4 或 letter。</translation>
    </message>
    <message>
        <source>report: --from and --to limit the scan of --all; without --all the record is of --address.</source>
        <translation>report：--from 和 --to 限定 --all 的扫描范围；不用 --all 时记录的是 --address 所指的驱动器。</translation>
    </message>
    <message>
        <source>report: --from %1 is above --to %2.</source>
        <translation>report：--from %1 大于 --to %2。</translation>
    </message>
    <message>
        <source>address %1: %2</source>
        <translation>地址 %1：%2</translation>
    </message>
    <message>
        <source>Drive %1 left out of the record: %2</source>
        <translation>驱动器 %1 未列入记录：%2</translation>
    </message>
    <message>
        <source>No Chinese font is installed: Chinese text cannot be drawn in the PDF. Install one (Debian: apt install fonts-noto-cjk).</source>
        <translation>未安装中文字体：PDF 中无法绘制中文。请安装一个（Debian：apt install fonts-noto-cjk）。</translation>
    </message>
    <message>
        <source>This family cannot scan.</source>
        <translation>此系列不能扫描。</translation>
    </message>
    <message>
        <source>No drive answered the scan; there is nothing to record.</source>
        <translation>扫描时没有驱动器应答；没有可记录的内容。</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) found; reading them.</source>
        <translation>
            <numerusform>找到 %n 台驱动器；正在读取。</numerusform>
        </translation>
    </message>
    <message>
        <source>Scanning addresses %1 to %2 ...</source>
        <translation>正在扫描地址 %1 到 %2 ...</translation>
    </message>
    <message>
        <source>There can be no drive at address %1 on this link.</source>
        <translation>此链路上不可能有地址为 %1 的驱动器。</translation>
    </message>
    <message>
        <source>No drive could be read; no record was written.</source>
        <translation>没有能读取的驱动器；未写入记录。</translation>
    </message>
    <message>
        <source>while this record was made</source>
        <translation>生成此记录期间</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message numerus="yes">
        <source>Commissioning record of %n drive(s) written to %1 (%2 pages).</source>
        <translation>
            <numerusform>%n 台驱动器的调试记录已写入 %1（%2 页）。</numerusform>
        </translation>
    </message>
    <message>
        <source>JSON: %1</source>
        <translation>JSON：%1</translation>
    </message>
    <message>
        <source>SHA-256 of the JSON: %1</source>
        <translation>JSON 的 SHA-256：%1</translation>
    </message>
    <message numerus="yes">
        <source>%n drive(s) failed their last verification; the record says so.</source>
        <translation>
            <numerusform>%n 台驱动器最近一次校验失败；记录中已注明。</numerusform>
        </translation>
    </message>
    <message>
        <source>report --runs: %1 was taken on a %2 drive; this link is of the %3 family.</source>
        <translation>report --runs：%1 是在 %2 驱动器上测得的；此链路属于 %3 系列。</translation>
    </message>
    <message>
        <source>report --runs: %1 was taken on the drive at address %2; this record is of address %3.</source>
        <translation>report --runs：%1 是在地址 %2 的驱动器上测得的；本记录针对地址 %3。</translation>
    </message>
    <message>
        <source>report --runs: &quot;%1&quot; has an empty file name; give RUN.ddrun,RUN2.ddrun,...</source>
        <translation>report --runs：“%1”中有空文件名；请写成 RUN.ddrun,RUN2.ddrun,...</translation>
    </message>
    <message>
        <source>report --runs: %1</source>
        <translation>report --runs：%1</translation>
    </message>
    <message>
        <source>report --runs: %1 is listed twice.</source>
        <translation>report --runs：%1 列出了两次。</translation>
    </message>
    <message>
        <source>Run %1 left out: its drive (address %2) could not be read.</source>
        <translation>运行 %1 未收入：其驱动器（地址 %2）无法读取。</translation>
    </message>
    <message>
        <source>run %1: its drive could not be read</source>
        <translation>运行 %1：其驱动器无法读取</translation>
    </message>
</context>
<context>
    <name>dd::RunsCommand</name>
    <message>
        <source>RUN.ddrun [RUN2.ddrun ...]</source>
        <translation>RUN.ddrun [RUN2.ddrun ...]</translation>
    </message>
    <message>
        <source>no tuning parameter differs</source>
        <translation>整定参数均无差异</translation>
    </message>
    <message>
        <source>%1 → %2: not comparable: %3</source>
        <translation>%1 → %2：不可比较：%3</translation>
    </message>
</context>
<context>
    <name>dd::SpectrumCommand</name>
    <message>
        <source>RUN.ddrun CHANNEL</source>
        <translation>RUN.ddrun CHANNEL</translation>
    </message>
    <message>
        <source>--peaks must be a whole number from 1 to 100, not &quot;%1&quot;.</source>
        <translation>--peaks 必须是 1 到 100 之间的整数，而不是“%1”。</translation>
    </message>
    <message>
        <source>--from must be a frequency ≥ 0 Hz, not &quot;%1&quot;.</source>
        <translation>--from 必须是 ≥ 0 Hz 的频率，而不是“%1”。</translation>
    </message>
    <message>
        <source>%1 has no channel &quot;%2&quot; (it has %3).</source>
        <translation>%1 中没有通道“%2”（有：%3）。</translation>
    </message>
    <message>
        <source>--between must be T1:T2, seconds from the trigger with T1 &lt; T2 (e.g. 0.05:0.3), not &quot;%1&quot;.</source>
        <translation>--between 必须为 T1:T2，即触发后的秒数且 T1 &lt; T2（例如 0.05:0.3），而不是 &quot;%1&quot;。</translation>
    </message>
    <message>
        <source>Spectrum of %1: %2 points at %3 Hz, %4 window, resolution %5 Hz, Nyquist %6 Hz</source>
        <translation>%1 的频谱：%2 个点，采样率 %3 Hz，%4 窗，分辨率 %5 Hz，奈奎斯特频率 %6 Hz</translation>
    </message>
    <message>
        <source>(may be an alias of %1 Hz)</source>
        <translation>（可能是 %1 Hz 的混叠）</translation>
    </message>
    <message>
        <source>(near the Nyquist frequency)</source>
        <translation>（接近奈奎斯特频率）</translation>
    </message>
</context>
<context>
    <name>dd::SourceDiffCommand</name>
    <message>
        <source>diff: the address of %1</source>
        <translation>diff：%1 的地址</translation>
    </message>
    <message>
        <source>diff: %1 is neither a file nor drive, drive:ADDRESS or defaults.</source>
        <translation>diff：%1 既不是文件，也不是 drive、drive:地址 或 defaults。</translation>
    </message>
    <message>
        <source>two sources</source>
        <translation>两个来源</translation>
    </message>
    <message>
        <source>%1 is a backup of a %2 drive and %3 of a %4 drive: parameters of different families have different meanings and are never compared.</source>
        <translation>%1 是 %2 驱动器的备份，%3 是 %4 驱动器的：不同系列的参数含义不同，从不比较。</translation>
    </message>
    <message>
        <source>%1 is a backup of a %2 drive; the drives on this link are %3 drives and are never compared with another family. To talk to %2 drives add --family %2.</source>
        <translation>%1 是 %2 驱动器的备份；此连接上是 %3 驱动器，从不与其他系列比较。要与 %2 驱动器通信，请加 --family %2。</translation>
    </message>
    <message>
        <source>drive %1: %2</source>
        <translation>驱动器 %1：%2</translation>
    </message>
    <message>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <source> (communication setting)</source>
        <translation>（通信设置）</translation>
    </message>
    <message>
        <source>Firmware differs: %1 has %2, %3 has %4.
</source>
        <translation>固件不同：%1 为 %2，%3 为 %4。
</translation>
    </message>
    <message>
        <source>%1 differ, %2 same (%3 / %4).</source>
        <translation>%1 个不同，%2 个相同（%3 / %4）。</translation>
    </message>
</context>
<context>
    <name>dd::CompareView</name>
    <message>
        <source>%1 is not added: %2</source>
        <translation>未添加 %1：%2</translation>
    </message>
    <message>
        <source>The %1 dictionary gives no default values (its manual publishes none); a dictionary file of your own can add them.</source>
        <translation>%1 参数字典没有默认值（其手册未公布）；可以用自己的字典文件添加。</translation>
    </message>
    <message>
        <source>drive %1 could not be read: %2</source>
        <translation>无法读取驱动器 %1：%2</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>%1
firmware %2</source>
        <translation>%1
固件 %2</translation>
    </message>
    <message>
        <source> (communication)</source>
        <translation>（通信）</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) differ.</source>
        <translation>
            <numerusform>%n 个参数不同。</numerusform>
        </translation>
    </message>
    <message>
        <source>The firmware differs between the sources: values may mean different things.</source>
        <translation>各来源的固件不同：数值的含义可能不同。</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>%1: drive %2</source>
        <translation>%1：驱动器 %2</translation>
    </message>
    <message>
        <source>No drive on an open link</source>
        <translation>已打开的连接上没有驱动器</translation>
    </message>
    <message>
        <source>Add a backup file</source>
        <translation>添加备份文件</translation>
    </message>
    <message>
        <source>DriveDesk backups (*.json *.ddbackup);;All files (*)</source>
        <translation>DriveDesk 备份 (*.json *.ddbackup);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Export the comparison</source>
        <translation>导出比较结果</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Compare parameters</source>
        <translation>比较参数</translation>
    </message>
    <message>
        <source>Add drive…</source>
        <translation>添加驱动器…</translation>
    </message>
    <message>
        <source>Add file…</source>
        <translation>添加文件…</translation>
    </message>
    <message>
        <source>Add defaults</source>
        <translation>添加默认值</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <source>Only differences</source>
        <translation>仅显示差异</translation>
    </message>
    <message>
        <source>Search parameters</source>
        <translation>搜索参数</translation>
    </message>
</context>
<context>
    <name>dd::FleetActions</name>
    <message>
        <source>Co&amp;mpare parameters…</source>
        <translation>比较参数(&amp;M)…</translation>
    </message>
    <message>
        <source>Apply a backup to several drives</source>
        <translation>将备份应用到多台驱动器</translation>
    </message>
    <message>
        <source>DriveDesk backups (*.json *.ddbackup);;All files (*)</source>
        <translation>DriveDesk 备份 (*.json *.ddbackup);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Apply backup</source>
        <translation>应用备份</translation>
    </message>
    <message>
        <source>%1 is a backup of a %2 drive; these are %3 drives. A backup is never applied to another family.</source>
        <translation>%1 是 %2 驱动器的备份；这些是 %3 驱动器。备份从不应用到其他系列。</translation>
    </message>
</context>
<context>
    <name>dd::FleetApplyDialog</name>
    <message>
        <source>drive %1</source>
        <translation>驱动器 %1</translation>
    </message>
    <message>
        <source>Reading drive %1…</source>
        <translation>正在读取驱动器 %1…</translation>
    </message>
    <message>
        <source>Drive %1 could not be read: %2. Nothing was written.</source>
        <translation>无法读取驱动器 %1：%2。未写入任何内容。</translation>
    </message>
    <message>
        <source>Reading the drives to plan the changes; nothing is written yet…</source>
        <translation>正在读取驱动器以规划更改；尚未写入任何内容…</translation>
    </message>
    <message numerus="yes">
        <source>Plan: %n parameter(s) to write in all. Only these are written; each is read back.</source>
        <translation>
            <numerusform>计划：共写入 %n 个参数。只写入这些参数，每个都会回读校验。</numerusform>
        </translation>
    </message>
    <message>
        <source>Write to the enabled or moving drive(s) %1 anyway: a parameter changed while the axis is energised takes effect at once and can make it jerk or move.</source>
        <translation>仍然写入已使能或正在运动的驱动器 %1：轴通电时更改的参数立即生效，可能使其抖动或运动。</translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>正在写入…</translation>
    </message>
    <message>
        <source>Done: %1 verified, %2 failed, %3 not attempted.</source>
        <translation>完成：%1 台已校验，%2 台失败，%3 台未尝试。</translation>
    </message>
    <message>
        <source>reading…</source>
        <translation>正在读取…</translation>
    </message>
    <message>
        <source>already matches: nothing to write</source>
        <translation>已一致：无需写入</translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) will change</source>
        <translation>
            <numerusform>将更改 %n 个参数</numerusform>
        </translation>
    </message>
    <message>
        <source>not planned: %1 — it will not be written</source>
        <translation>未能规划：%1 — 不会写入</translation>
    </message>
    <message>
        <source>writing…</source>
        <translation>正在写入…</translation>
    </message>
    <message numerus="yes">
        <source>verified: %n parameter(s) written and read back</source>
        <translation>
            <numerusform>已校验：%n 个参数已写入并回读</numerusform>
        </translation>
    </message>
    <message>
        <source>FAILED: %1 (written: %2; not written or unknown: %3)</source>
        <translation>失败：%1（已写入：%2；未写入或未知：%3）</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>not attempted (an earlier drive failed)</source>
        <translation>未尝试（之前的驱动器失败）</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>left alone: a communication setting (stays %1)</source>
        <translation>保持不变：通信设置（仍为 %1）</translation>
    </message>
    <message>
        <source>Apply to several drives</source>
        <translation>应用到多台驱动器</translation>
    </message>
    <message>
        <source>From %1 to the drives %2. Communication settings (address, baud rate, station number) are left alone.</source>
        <translation>从 %1 到驱动器 %2。通信设置（地址、波特率、站号）保持不变。</translation>
    </message>
    <message>
        <source>(no source yet)</source>
        <translation>（尚无来源）</translation>
    </message>
    <message>
        <source>Drive / parameter</source>
        <translation>驱动器 / 参数</translation>
    </message>
    <message>
        <source>Plan and result</source>
        <translation>计划与结果</translation>
    </message>
    <message>
        <source>Stop at the first failed drive</source>
        <translation>在第一台失败的驱动器处停止</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
</context>
<context>
    <name>dd::LinkHealthDock</name>
    <message>
        <source>%1, address %2</source>
        <translation>%1，地址 %2</translation>
    </message>
    <message>
        <source>%1 / %2 / %3 ms</source>
        <translation>%1 / %2 / %3 毫秒</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 毫秒</translation>
    </message>
    <message>
        <source>Link health</source>
        <translation>链路健康</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>驱动器</translation>
    </message>
    <message>
        <source>Requests</source>
        <translation>请求</translation>
    </message>
    <message>
        <source>Answered</source>
        <translation>已应答</translation>
    </message>
    <message>
        <source>Turnaround min / median / max</source>
        <translation>往返时间 最小 / 中位数 / 最大</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>超时</translation>
    </message>
    <message>
        <source>Checksum errors</source>
        <translation>校验错误</translation>
    </message>
    <message>
        <source>Late or duplicated</source>
        <translation>迟到或重复</translation>
    </message>
    <message>
        <source>Retries</source>
        <translation>重试</translation>
    </message>
    <message>
        <source>Recommended timeout</source>
        <translation>建议超时</translation>
    </message>
    <message>
        <source>Recommended gap</source>
        <translation>建议间隔</translation>
    </message>
    <message>
        <source>Sent on a busy line</source>
        <translation>在繁忙线路上发送</translation>
    </message>
    <message>
        <source>From the traffic seen so far. The recommended timeout is the reply allowance beyond the wire time (drivedesk-cli --timeout); the gap is the quiet time between requests that lets late replies land first. Requests sent on a busy line went out although the line was never quiet (another master on the bus, or a drive sending on its own): no timeout or gap helps there.</source>
        <translation>根据目前已观察到的通信统计。建议超时是线路传输时间之外的应答余量（drivedesk-cli --timeout）；间隔是请求之间的静默时间，让迟到的应答先到达。“在繁忙线路上发送”的请求是在线路一直不静默时发出的（总线上有另一个主站，或有驱动器在自行发送）：任何超时或间隔都无济于事。</translation>
    </message>
</context>
<context>
    <name>dd::RecordAction</name>
    <message>
        <source>Commissioning &amp;record…</source>
        <translation>调试记录(&amp;R)…</translation>
    </message>
    <message>
        <source>A PDF (and JSON) record of the drives: what was set, verified and measured</source>
        <translation>驱动器的 PDF（及 JSON）记录：设置了什么、校验了什么、测量了什么</translation>
    </message>
</context>
<context>
    <name>dd::RecordDialog</name>
    <message>
        <source>Reading drive %1 of %2 …</source>
        <translation>正在读取驱动器 %1/%2 …</translation>
    </message>
    <message>
        <source>Commissioning record</source>
        <translation>调试记录</translation>
    </message>
    <message>
        <source>Drives in the record:</source>
        <translation>记录中的驱动器：</translation>
    </message>
    <message>
        <source>Machine / project:</source>
        <translation>机器 / 项目：</translation>
    </message>
    <message>
        <source>Customer:</source>
        <translation>客户：</translation>
    </message>
    <message>
        <source>Site:</source>
        <translation>现场：</translation>
    </message>
    <message>
        <source>Engineer:</source>
        <translation>工程师：</translation>
    </message>
    <message>
        <source>Notes:</source>
        <translation>备注：</translation>
    </message>
    <message>
        <source>Paper:</source>
        <translation>纸张：</translation>
    </message>
    <message>
        <source>Letter</source>
        <translation>Letter（信纸）</translation>
    </message>
    <message>
        <source>&amp;Preview</source>
        <translation>预览(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Save PDF…</source>
        <translation>保存 PDF(&amp;S)…</translation>
    </message>
    <message>
        <source>%1 at address %2 — %3</source>
        <translation>%1，地址 %2 — %3</translation>
    </message>
    <message>
        <source>No drive is connected: connect to the drives first (File → Connect…).</source>
        <translation>没有连接驱动器：请先连接驱动器（文件 → 连接…）。</translation>
    </message>
    <message>
        <source>Save the commissioning record</source>
        <translation>保存调试记录</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF 文件 (*.pdf)</translation>
    </message>
    <message>
        <source>Choose at least one drive for the record.</source>
        <translation>请为记录至少选择一台驱动器。</translation>
    </message>
    <message>
        <source>No drive could be read: %1</source>
        <translation>没有能读取的驱动器：%1</translation>
    </message>
    <message>
        <source>Left out: %1</source>
        <translation>未列入：%1</translation>
    </message>
    <message numerus="yes">
        <source>Preview of the first %n page(s).</source>
        <translation>
            <numerusform>前 %n 页的预览。</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message numerus="yes">
        <source>Saved %1 (%n page(s)) and %2. SHA-256 of the JSON: %3</source>
        <translation>
            <numerusform>已保存 %1（%n 页）和 %2。JSON 的 SHA-256：%3</numerusform>
        </translation>
    </message>
    <message>
        <source>No Chinese font is installed: Chinese text is missing from the PDF.</source>
        <translation>未安装中文字体：PDF 中缺少中文文字。</translation>
    </message>
    <message>
        <source>Tuning runs (run files, each shown with the drive it was taken on):</source>
        <translation>调试运行（运行文件，各自显示在其所测的驱动器下）：</translation>
    </message>
    <message>
        <source>Add run files…</source>
        <translation>添加运行文件…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>%1 — %2, %3 at address %4</source>
        <translation>%1 — %2，%3，地址 %4</translation>
    </message>
    <message>
        <source>Not added: %1</source>
        <translation>未添加：%1</translation>
    </message>
    <message>
        <source>Choose tuning runs for the record</source>
        <translation>选择要收入记录的调试运行</translation>
    </message>
    <message>
        <source>Run files (*.ddrun)</source>
        <translation>运行文件 (*.ddrun)</translation>
    </message>
    <message>
        <source>No record was made: %1</source>
        <translation>未生成记录：%1</translation>
    </message>
    <message>
        <source>Also keeps this machine&apos;s drives apart in the verification journal: the writes, restores and EEPROM operations made from now on are noted under this name, and a record shows those noted under the name it is made with.</source>
        <translation>同时用于在校验日志中区分本机器的驱动器：此后的写入、恢复和 EEPROM 操作都记在此名称下，调试记录只显示记在生成时所用名称下的内容。</translation>
    </message>
</context>
<context>
    <name>dd::RecordGatherer</name>
    <message>
        <source>%1 at address %2: %3</source>
        <translation>%1，地址 %2：%3</translation>
    </message>
</context>
<context>
    <name>dd::RecordSession</name>
    <message>
        <source>since the connection was opened</source>
        <translation>自连接打开以来</translation>
    </message>
</context>
<context>
    <name>dd::StopReporter</name>
    <message>
        <source>%1: stop sent, waiting for its state…</source>
        <translation>%1：已发送停止，正在等待其状态…</translation>
    </message>
    <message>
        <source>%1: stopped (the drive reports the axis at rest).</source>
        <translation>%1：已停止（驱动器报告轴已静止）。</translation>
    </message>
    <message>
        <source>%1: has no stop command; it is at rest.</source>
        <translation>%1：没有停止命令；它处于静止状态。</translation>
    </message>
    <message>
        <source>%1: has no stop command and is still moving; DriveDesk cannot stop it. Use the machine&apos;s emergency stop or switch off the drive&apos;s servo-on input.</source>
        <translation>%1：没有停止命令且仍在运动；DriveDesk 无法停止它。请使用机器的急停，或关闭驱动器的伺服使能输入。</translation>
    </message>
    <message>
        <source>%1: STOP failed: the drive still reports motion.</source>
        <translation>%1：停止失败：驱动器仍报告在运动。</translation>
    </message>
    <message>
        <source>%1: STOP failed: %2</source>
        <translation>%1：停止失败：%2</translation>
    </message>
    <message>
        <source>STOP sent; no drive is connected.</source>
        <translation>已发送停止；没有连接任何驱动器。</translation>
    </message>
    <message>
        <source>STOP: %1</source>
        <translation>停止：%1</translation>
    </message>
    <message>
        <source>%1: stopped (the drive reports the axis at rest); STOP switched its power stage off.</source>
        <translation>%1：已停止（驱动器报告轴已静止）；停止已关闭其功率级。</translation>
    </message>
    <message>
        <source>What STOP did, drive by drive:</source>
        <translation>停止对各驱动器的结果：</translation>
    </message>
</context>
<context>
    <name>dd::RunParameterApply</name>
    <message>
        <source>The run holds no tuning parameters to apply.</source>
        <translation>该运行记录中没有可应用的调谐参数。</translation>
    </message>
    <message>
        <source>The run was taken on a %1 drive; this drive is %2.</source>
        <translation>该运行记录采集自 %1 驱动器；本驱动器为 %2。</translation>
    </message>
    <message>
        <source>The run&apos;s parameter %1 (index %2) is not that parameter in the drive&apos;s dictionary.</source>
        <translation>运行记录中的参数 %1（索引 %2）在驱动器的参数字典中并非该参数。</translation>
    </message>
    <message>
        <source>The run&apos;s %1 = %2 cannot be applied: %3</source>
        <translation>运行记录中的 %1 = %2 无法应用：%3</translation>
    </message>
    <message>
        <source>The drive is gone.</source>
        <translation>驱动器已不存在。</translation>
    </message>
    <message>
        <source>A backup or restore is already running on this drive.</source>
        <translation>该驱动器上已有备份或恢复正在进行。</translation>
    </message>
    <message>
        <source>The whole run is refused; nothing was written.</source>
        <translation>整个运行记录被拒绝；未写入任何数据。</translation>
    </message>
    <message>
        <source>The drive&apos;s dictionary (%1) names no tuning parameters, so nothing tells a loop gain from a setting: apply-run writes only parameters whose role in the drive&apos;s dictionary is a tuning role.</source>
        <translation>驱动器的参数字典（%1）未指定任何调试参数，因此无法区分环路增益和设置：apply-run 只写入在驱动器字典中具有调试角色的参数。</translation>
    </message>
    <message>
        <source>The run was recorded with a dictionary that gives them roles (%1): DriveDesk&apos;s simulator names its own loop gains so, which mean something else, or nothing, on a real drive.</source>
        <translation>该运行记录所用的字典为它们指定了角色（%1）：DriveDesk 模拟器这样命名它自己的环路增益，在真实驱动器上它们含义不同，或毫无意义。</translation>
    </message>
    <message>
        <source>Nothing was written.</source>
        <translation>未写入任何数据。</translation>
    </message>
    <message>
        <source>The run&apos;s %1 has the role %2; in the drive&apos;s dictionary (%3) it is %4: the run was recorded with another dictionary. Nothing was written.</source>
        <translation>运行记录中 %1 的角色是 %2；在驱动器的字典（%3）中它是 %4：该运行记录是用另一个字典记录的。未写入任何数据。</translation>
    </message>
    <message>
        <source>The run lists parameters that are not tuning parameters in the drive&apos;s dictionary (%1): %2. apply-run writes only tuning parameters; the whole run is refused and nothing was written.</source>
        <translation>运行记录列出了在驱动器字典（%1）中不是调试参数的参数：%2。apply-run 只写入调试参数；整个运行记录被拒绝，未写入任何数据。</translation>
    </message>
    <message>
        <source>The run was taken on a %1; this drive is a %2. Tuning values do not carry over between models; nothing was written.</source>
        <translation>该运行记录取自 %1；此驱动器是 %2。调试值不能在不同型号之间通用；未写入任何数据。</translation>
    </message>
</context>
<context>
    <name>dd::StepLimits</name>
    <message>
        <source>A step test needs limits: a maximum speed, a maximum travel from the start position and a maximum duration.</source>
        <translation>阶跃测试需要限值：最大速度、距起始位置的最大行程和最长时间。</translation>
    </message>
    <message>
        <source>The maximum speed is not set.</source>
        <translation>未设置最大速度。</translation>
    </message>
    <message>
        <source>The maximum travel is not set.</source>
        <translation>未设置最大行程。</translation>
    </message>
    <message>
        <source>The maximum duration is not set.</source>
        <translation>未设置最长时间。</translation>
    </message>
    <message>
        <source>The step&apos;s speed %1 is above the maximum speed %2.</source>
        <translation>阶跃速度 %1 超过最大速度 %2。</translation>
    </message>
    <message>
        <source>The step&apos;s distance %1 is beyond the maximum travel %2.</source>
        <translation>阶跃距离 %1 超出最大行程 %2。</translation>
    </message>
    <message>
        <source>The step runs for %1 s, which leaves no time to stop within the maximum duration of %2 s.</source>
        <translation>阶跃运行 %1 秒，在最长时间 %2 秒内没有留出停止的时间。</translation>
    </message>
</context>
<context>
    <name>dd::StepSpec</name>
    <message>
        <source>A position step needs a distance other than 0.</source>
        <translation>定位阶跃需要不为 0 的距离。</translation>
    </message>
    <message>
        <source>A position step needs a speed above 0.</source>
        <translation>定位阶跃需要大于 0 的速度。</translation>
    </message>
    <message>
        <source>A %1 step needs a speed other than 0.</source>
        <translation>%1 阶跃需要不为 0 的速度。</translation>
    </message>
    <message>
        <source>A %1 step needs a duration from 0 to 3600 s.</source>
        <translation>%1 阶跃需要 0 到 3600 秒之间的时长。</translation>
    </message>
    <message>
        <source>The capture before the motion must be 0 to 10 s.</source>
        <translation>运动前的采集时间必须为 0 到 10 秒。</translation>
    </message>
    <message>
        <source>The capture after the motion command must be 0 to 600 s.</source>
        <translation>运动指令后的采集时间必须为 0 到 600 秒。</translation>
    </message>
    <message>
        <source>The settling time recorded after the motion must be 0 to 60 s.</source>
        <translation>运动后记录的稳定时间必须为 0 到 60 秒。</translation>
    </message>
    <message>
        <source>The counts per revolution must be 1 to 1000000000.</source>
        <translation>每转计数必须在 1 到 1000000000 之间。</translation>
    </message>
</context>
<context>
    <name>dd::StepTest</name>
    <message>
        <source>The motion was not at rest within the maximum duration of %1 s; stopped.</source>
        <translation>运动未在最长时间 %1 秒内静止；已停止。</translation>
    </message>
    <message>
        <source>The drive raised alarm %1 during the step test.</source>
        <translation>阶跃测试期间驱动器发出报警 %1。</translation>
    </message>
    <message>
        <source>STOP: the step test was stopped.</source>
        <translation>停止：阶跃测试已停止。</translation>
    </message>
    <message>
        <source>The jog lease ran out and the drive stopped the axis.</source>
        <translation>点动租约已到期，驱动器已停止该轴。</translation>
    </message>
    <message>
        <source>The link was lost during the step test (%1).</source>
        <translation>阶跃测试期间链路断开（%1）。</translation>
    </message>
    <message>
        <source>No drive to test.</source>
        <translation>没有可测试的驱动器。</translation>
    </message>
    <message>
        <source>This drive cannot run a %1 step: %2</source>
        <translation>该驱动器无法进行 %1 阶跃：%2</translation>
    </message>
    <message>
        <source>This drive cannot move back to the start position; run the test without returning.</source>
        <translation>该驱动器无法回到起始位置；请在不返回的情况下进行测试。</translation>
    </message>
    <message>
        <source>This drive offers no %1 channel, which the step test&apos;s limits are watched on.</source>
        <translation>该驱动器没有 %1 通道，而阶跃测试的限值要靠它监视。</translation>
    </message>
    <message>
        <source>This drive has no channel %1.</source>
        <translation>该驱动器没有通道 %1。</translation>
    </message>
    <message>
        <source>A step test is already running.</source>
        <translation>已有阶跃测试正在进行。</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s state and tuning parameters.</source>
        <translation>正在读取驱动器状态和调谐参数。</translation>
    </message>
    <message>
        <source>Could not read the drive&apos;s state: %1</source>
        <translation>无法读取驱动器状态：%1</translation>
    </message>
    <message>
        <source>Could not read the tuning parameters: %1</source>
        <translation>无法读取调谐参数：%1</translation>
    </message>
    <message>
        <source>The capture failed: %1</source>
        <translation>采集失败：%1</translation>
    </message>
    <message>
        <source>Capturing %1 before the motion.</source>
        <translation>运动前开始采集 %1。</translation>
    </message>
    <message>
        <source>The start position is unknown: the travel limit cannot be watched.</source>
        <translation>起始位置未知：无法监视行程限值。</translation>
    </message>
    <message>
        <source>Moving by %1 at %2.</source>
        <translation>以 %2 移动 %1。</translation>
    </message>
    <message>
        <source>Running at %1 for %2 s.</source>
        <translation>以 %1 运行 %2 秒。</translation>
    </message>
    <message>
        <source>The speed reached %1, above the maximum speed %2; stopped.</source>
        <translation>速度达到 %1，超过最大速度 %2；已停止。</translation>
    </message>
    <message>
        <source>The axis travelled %1 from the start, beyond the maximum travel %2; stopped.</source>
        <translation>轴从起始位置移动了 %1，超出最大行程 %2；已停止。</translation>
    </message>
    <message>
        <source>Waiting for the axis to come to rest.</source>
        <translation>正在等待轴静止。</translation>
    </message>
    <message>
        <source>Could not return to the start position: %1</source>
        <translation>无法返回起始位置：%1</translation>
    </message>
    <message>
        <source>The axis came to rest at %1, not at the start position %2.</source>
        <translation>轴静止在 %1，而不是起始位置 %2。</translation>
    </message>
    <message>
        <source>Stopping the axis: %1</source>
        <translation>正在停止该轴：%1</translation>
    </message>
    <message>
        <source>No stop could be sent: the drive&apos;s own watchdog stops the axis; check that it has stopped.</source>
        <translation>无法发送停止指令：由驱动器自身的看门狗停止该轴；请确认轴已停止。</translation>
    </message>
    <message>
        <source>No stop could be sent: the axis may still be moving; use the machine&apos;s emergency stop.</source>
        <translation>无法发送停止指令：轴可能仍在运动；请使用机器的急停。</translation>
    </message>
    <message>
        <source>STOP FAILED: %1 The drive&apos;s own watchdog stops the axis when it hears nothing from us; check that it has stopped.</source>
        <translation>停止失败：%1 驱动器收不到我们的消息时由其自身的看门狗停止该轴；请确认轴已停止。</translation>
    </message>
    <message>
        <source>STOP FAILED: %1 The axis may still be moving: use the machine&apos;s emergency stop.</source>
        <translation>停止失败：%1 轴可能仍在运动：请使用机器的急停。</translation>
    </message>
    <message>
        <source>The stop was sent, but the axis could not be seen at rest: %1</source>
        <translation>停止指令已发送，但无法确认轴已静止：%1</translation>
    </message>
    <message>
        <source>The axis was not seen at rest %1 s after the stop: check it; use the machine&apos;s emergency stop if it still moves.</source>
        <translation>停止后 %1 秒仍未见轴静止：请检查；若仍在运动，请使用机器的急停。</translation>
    </message>
    <message>
        <source>Step test completed.</source>
        <translation>阶跃测试完成。</translation>
    </message>
    <message>
        <source>Step test aborted: %1</source>
        <translation>阶跃测试中止：%1</translation>
    </message>
    <message>
        <source>Step test not run: %1</source>
        <translation>阶跃测试未进行：%1</translation>
    </message>
    <message>
        <source>Alarm %1 is active: clear it first. No motion was sent.</source>
        <translation>报警 %1 处于激活状态：请先清除。未发送任何运动指令。</translation>
    </message>
    <message>
        <source>This drive&apos;s speed unit &quot;%1&quot; is not one DriveDesk can relate to positions: the test&apos;s travel cannot be predicted.</source>
        <translation>该驱动器的速度单位“%1”无法与位置换算：无法预测测试的行程。</translation>
    </message>
    <message>
        <source>%1 %2 %3, the drive&apos;s</source>
        <translation>%1 %2 %3，驱动器的设定</translation>
    </message>
    <message>
        <source>assumed: a stop from the test&apos;s speed within %1 s; the dictionary names no deceleration</source>
        <translation>假定：从测试速度在 %1 s 内停止；参数字典中没有减速度</translation>
    </message>
    <message>
        <source>No motion was sent.</source>
        <translation>未发送任何运动指令。</translation>
    </message>
    <message>
        <source>At %1 from the start the axis needs about %2 more to stop: it would pass the maximum travel %3; stopped.</source>
        <translation>距起始位置 %1 处，轴还需约 %2 才能停下：将超过最大行程 %3；已停止。</translation>
    </message>
    <message>
        <source>Stopped by another master or at the drive: %1. DriveDesk sends no further motion (no return to the start).</source>
        <translation>被其他主站或在驱动器处停止：%1。DriveDesk 不再发送任何运动指令（不返回起始位置）。</translation>
    </message>
    <message>
        <source>the move came to rest at %1, %2 short of its target %3</source>
        <translation>运动停在 %1，距目标 %3 还差 %2</translation>
    </message>
    <message>
        <source>not measured: the test was aborted (%1)</source>
        <translation>未测量：测试已中止（%1）</translation>
    </message>
    <message>
        <source> (aborted)</source>
        <translation>（已中止）</translation>
    </message>
    <message>
        <source>Not returning to the start position %1: it is %2 away, beyond the maximum travel %3.</source>
        <translation>不返回起始位置 %1：相距 %2，超出最大行程 %3。</translation>
    </message>
    <message>
        <source>Returning to the start position %1: moving %2 at %3 (STOP stops it).</source>
        <translation>正在返回起始位置 %1：以 %3 移动 %2（STOP 可停止）。</translation>
    </message>
    <message>
        <source>the return to the start came to rest at %1, %2 from the start %3</source>
        <translation>返回起始位置的运动停在 %1，距起始位置 %3 为 %2</translation>
    </message>
    <message>
        <source>The axis stopped at %1 (%2 from the start; farthest %3 of the maximum travel %4).</source>
        <translation>轴停在 %1（距起始位置 %2；最远 %3，最大行程 %4）。</translation>
    </message>
</context>
<context>
    <name>dd::ApplyRunCommand</name>
    <message>
        <source>RUN.ddrun</source>
        <translation>RUN.ddrun</translation>
    </message>
    <message>
        <source>Finishing the writes in progress so that the report is complete; every write is verified as it goes.</source>
        <translation>正在完成进行中的写入以保证报告完整；每次写入都会随即校验。</translation>
    </message>
    <message>
        <source>The drive&apos;s tuning parameters already match %1; nothing to write.</source>
        <translation>驱动器的调谐参数已与 %1 一致；无需写入。</translation>
    </message>
    <message numerus="yes">
        <source>Dry run: %n parameter(s) would be written; nothing was sent.</source>
        <translation>
            <numerusform>试运行：将写入 %n 个参数；未发送任何数据。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n parameter(s) written and verified.</source>
        <translation>
            <numerusform>已写入并校验 %n 个参数。</numerusform>
        </translation>
    </message>
    <message>
        <source>The values are in the drive&apos;s RAM; `ee set` stores them to EEPROM.</source>
        <translation>这些值位于驱动器的 RAM 中；`ee set` 可将其存入 EEPROM。</translation>
    </message>
</context>
<context>
    <name>dd::StepCommand</name>
    <message>
        <source>velocity SPEED | position DISTANCE | reversal SPEED</source>
        <translation>velocity SPEED | position DISTANCE | reversal SPEED</translation>
    </message>
    <message>
        <source>The step test must be velocity, position or reversal, not &quot;%1&quot;.</source>
        <translation>阶跃测试必须为 velocity、position 或 reversal，而不是 &quot;%1&quot;。</translation>
    </message>
    <message>
        <source>distance</source>
        <translation>距离</translation>
    </message>
    <message>
        <source>A position step needs --speed V.</source>
        <translation>定位阶跃需要 --speed V。</translation>
    </message>
    <message>
        <source>--duration is for velocity and reversal steps; a position step ends when it arrives.</source>
        <translation>--duration 用于速度阶跃和反向阶跃；定位阶跃在到位时结束。</translation>
    </message>
    <message>
        <source>step speed</source>
        <translation>阶跃速度</translation>
    </message>
    <message>
        <source>--speed is for position steps; the speed of a %1 step is its argument.</source>
        <translation>--speed 用于定位阶跃；%1 阶跃的速度由其参数给出。</translation>
    </message>
    <message>
        <source>A %1 step needs --duration S.</source>
        <translation>%1 阶跃需要 --duration S。</translation>
    </message>
    <message>
        <source>A step test needs its limits: --max-speed V is missing (nothing was sent).</source>
        <translation>阶跃测试需要限值：缺少 --max-speed V（未发送任何内容）。</translation>
    </message>
    <message>
        <source>A step test needs its limits: --max-travel N is missing (nothing was sent).</source>
        <translation>阶跃测试需要限值：缺少 --max-travel N（未发送任何内容）。</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>未发送任何内容。</translation>
    </message>
    <message>
        <source>Second interrupt: emergency stop.</source>
        <translation>第二次中断：急停。</translation>
    </message>
    <message>
        <source>Interrupted: the step test was stopped.</source>
        <translation>已中断：阶跃测试已停止。</translation>
    </message>
    <message>
        <source>%1 %2: %3 samples of %4, interval %5 ms (%6 Hz); metrics on %7</source>
        <translation>%1 %2：%4 共 %3 个采样，间隔 %5 毫秒（%6 Hz）；指标基于 %7</translation>
    </message>
    <message>
        <source>  tuning: %1</source>
        <translation>  调谐参数：%1</translation>
    </message>
    <message>
        <source>  saved to %1</source>
        <translation>  已保存到 %1</translation>
    </message>
    <message>
        <source>Back at the start position %1.</source>
        <translation>已回到起始位置 %1。</translation>
    </message>
    <message>
        <source>Left at %1 (--no-return; started at %2).</source>
        <translation>停留在 %1（--no-return；起始于 %2）。</translation>
    </message>
    <message>
        <source>--pre %1 is %2 s before the motion: at most 10 s.</source>
        <translation>--pre %1 相当于运动前 %2 s：最多 10 s。</translation>
    </message>
    <message>
        <source>No command was sent after identifying the drive.</source>
        <translation>识别驱动器之后未发送任何指令。</translation>
    </message>
</context>
<context>
    <name>dd::RecordRuns</name>
    <message>
        <source>Capture</source>
        <translation>采集</translation>
    </message>
    <message>
        <source>Velocity step</source>
        <translation>速度阶跃</translation>
    </message>
    <message>
        <source>Position step</source>
        <translation>位置阶跃</translation>
    </message>
    <message>
        <source>Reversal</source>
        <translation>换向</translation>
    </message>
    <message>
        <source>Rise time (10–90 %)</source>
        <translation>上升时间（10–90 %）</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>超调量</translation>
    </message>
    <message>
        <source>Settling time (±2 %)</source>
        <translation>调节时间（±2 %）</translation>
    </message>
    <message>
        <source>Settling time (±5 %)</source>
        <translation>调节时间（±5 %）</translation>
    </message>
    <message>
        <source>Steady-state error</source>
        <translation>稳态误差</translation>
    </message>
    <message>
        <source>Steady-state ripple</source>
        <translation>稳态波动</translation>
    </message>
    <message>
        <source>Peak following error</source>
        <translation>最大跟随误差</translation>
    </message>
    <message>
        <source>Peak torque</source>
        <translation>峰值转矩</translation>
    </message>
    <message>
        <source>Peak current</source>
        <translation>峰值电流</translation>
    </message>
    <message>
        <source>Sample interval</source>
        <translation>采样间隔</translation>
    </message>
    <message>
        <source>Cannot open the run file %1: %2</source>
        <translation>无法打开运行文件 %1：%2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MiB: not a run file</source>
        <translation>%1 大于 %2 MiB：不是运行文件</translation>
    </message>
    <message>
        <source>The run file %1 is chosen twice.</source>
        <translation>运行文件 %1 被选了两次。</translation>
    </message>
    <message>
        <source>%1 at %2</source>
        <translation>%1，地址 %2</translation>
    </message>
    <message>
        <source>The run %1 was taken on %2 at address %3, which is not in this record (it holds %4).</source>
        <translation>运行 %1 是在 %2（地址 %3）上测得的，该驱动器不在本记录中（本记录包含：%4）。</translation>
    </message>
    <message>
        <source>no drive</source>
        <translation>无驱动器</translation>
    </message>
</context>
<context>
    <name>dd::RunPlot</name>
    <message>
        <source>time from the trigger (s)</source>
        <translation>相对触发点的时间（s）</translation>
    </message>
    <message>
        <source>%1: no sample</source>
        <translation>%1：无采样</translation>
    </message>
</context>
<context>
    <name>dd::HelpActions</name>
    <message>
        <source>&amp;User guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
</context>
<context>
    <name>dd::ShortcutsDialog</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <source>What they do</source>
        <translation>作用</translation>
    </message>
    <message>
        <source>Open the user guide</source>
        <translation>打开用户指南</translation>
    </message>
    <message>
        <source>Connect… (open a port or CAN interface and scan it)</source>
        <translation>连接…（打开串口或 CAN 接口并扫描）</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>退出</translation>
    </message>
    <message>
        <source>Hold %1 on a jog button</source>
        <translation>在点动按钮上按住 %1</translation>
    </message>
    <message>
        <source>Motion: jog while held; letting go stops</source>
        <translation>运动：按住时点动，松开即停止</translation>
    </message>
    <message>
        <source>Parameters: undo / redo an edit</source>
        <translation>参数：撤销 / 重做编辑</translation>
    </message>
    <message>
        <source>Parameters: copy the selected rows (also in the right-click menu)</source>
        <translation>参数：复制所选行（右键菜单中也有）</translation>
    </message>
    <message>
        <source>Trend: zoom in / out</source>
        <translation>趋势：放大 / 缩小</translation>
    </message>
    <message>
        <source>Trend: pan in time</source>
        <translation>趋势：沿时间平移</translation>
    </message>
    <message>
        <source>Trend: reset the zoom</source>
        <translation>趋势：复位缩放</translation>
    </message>
    <message>
        <source>Alt + underlined letter</source>
        <translation>Alt + 带下划线的字母</translation>
    </message>
    <message>
        <source>Menus and buttons: the letter underlined in their name</source>
        <translation>菜单和按钮：名称中带下划线的字母</translation>
    </message>
    <message>
        <source>Trend and Tuning plots: remove the cursors</source>
        <translation>趋势与整定图：移除光标</translation>
    </message>
    <message>
        <source>STOP: stop every drive on every connection, from any window, dialog, menu or editor (Esc then also closes the dialog; F12 only stops)</source>
        <translation>STOP：停止所有连接上的所有驱动器，在任何窗口、对话框、菜单或编辑器中均有效（Esc 随后还会关闭对话框；F12 只停止）</translation>
    </message>
</context>
<context>
    <name>dd::UserGuideDialog</name>
    <message>
        <source>userguide-en.md</source>
        <translation>userguide-zh_CN.md</translation>
    </message>
    <message>
        <source>DriveDesk user guide</source>
        <translation>DriveDesk 用户指南</translation>
    </message>
    <message>
        <source>The user guide is missing from this build.</source>
        <translation>此版本缺少用户指南。</translation>
    </message>
</context>
<context>
    <name>dd::MotionReadout</name>
    <message>
        <source>Left limit</source>
        <translation>左限位</translation>
    </message>
    <message>
        <source>Origin</source>
        <translation>原点</translation>
    </message>
    <message>
        <source>Right limit</source>
        <translation>右限位</translation>
    </message>
    <message>
        <source>%1: not read yet</source>
        <translation>%1：尚未读取</translation>
    </message>
    <message>
        <source>%1: active</source>
        <translation>%1：已触发</translation>
    </message>
    <message>
        <source>%1: not active</source>
        <translation>%1：未触发</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Following error</source>
        <translation>跟随误差</translation>
    </message>
</context>
<context>
    <name>dd::ParameterContextMenu</name>
    <message numerus="yes">
        <source>&amp;Copy %n rows</source>
        <translation>
            <numerusform>复制 %n 行(&amp;C)</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Copy</source>
        <translation>复制(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Reset to default (%1)</source>
        <translation>恢复默认值（%1）(&amp;R)</translation>
    </message>
    <message>
        <source>Reset to default (read-only parameter)</source>
        <translation>恢复默认值（只读参数）</translation>
    </message>
    <message>
        <source>Reset to default (the dictionary gives none)</source>
        <translation>恢复默认值（参数字典未给出默认值）</translation>
    </message>
    <message>
        <source>&amp;Write this row</source>
        <translation>写入此行(&amp;W)</translation>
    </message>
    <message>
        <source>Write this row (not edited)</source>
        <translation>写入此行（未编辑）</translation>
    </message>
</context>
<context>
    <name>dd::CaptureControls</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>At once</source>
        <translation>立即</translation>
    </message>
    <message>
        <source>Rising through level</source>
        <translation>上升穿过电平</translation>
    </message>
    <message>
        <source>Falling through level</source>
        <translation>下降穿过电平</translation>
    </message>
    <message>
        <source>Either way through level</source>
        <translation>双向穿过电平</translation>
    </message>
    <message>
        <source>Above level</source>
        <translation>高于电平</translation>
    </message>
    <message>
        <source>Below level</source>
        <translation>低于电平</translation>
    </message>
    <message>
        <source>Alarm raised</source>
        <translation>出现报警</translation>
    </message>
    <message>
        <source>Single</source>
        <translation>单次</translation>
    </message>
    <message>
        <source>Normal (re-arm)</source>
        <translation>常规（自动重新布防）</translation>
    </message>
    <message>
        <source>Auto (time-out)</source>
        <translation>自动（超时触发）</translation>
    </message>
    <message>
        <source>Trigger:</source>
        <translation>触发：</translation>
    </message>
    <message>
        <source>Channel:</source>
        <translation>通道：</translation>
    </message>
    <message>
        <source>Level:</source>
        <translation>电平：</translation>
    </message>
    <message>
        <source>Pre-trigger:</source>
        <translation>预触发：</translation>
    </message>
    <message>
        <source>Length:</source>
        <translation>时长：</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>模式：</translation>
    </message>
    <message>
        <source>Auto after:</source>
        <translation>超时：</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>布防</translation>
    </message>
    <message>
        <source>Force</source>
        <translation>强制触发</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Start sampling; the capture is taken when the trigger fires.</source>
        <translation>开始采样；触发条件满足时进行捕获。</translation>
    </message>
    <message>
        <source>Fire the trigger now.</source>
        <translation>立即触发。</translation>
    </message>
</context>
<context>
    <name>dd::CapturePlot</name>
    <message>
        <source>Click the plot to place cursor A, Shift + click for cursor B.</source>
        <translation>单击曲线图放置光标 A，Shift + 单击放置光标 B。</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 毫秒</translation>
    </message>
    <message>
        <source>A: %1</source>
        <translation>A：%1</translation>
    </message>
    <message>
        <source>B: %1</source>
        <translation>B：%1</translation>
    </message>
    <message>
        <source>Δt: %1</source>
        <translation>Δt：%1</translation>
    </message>
    <message>
        <source>A %1</source>
        <translation>A %1</translation>
    </message>
    <message>
        <source>B %1</source>
        <translation>B %1</translation>
    </message>
    <message>
        <source>Δvalue %1</source>
        <translation>Δ值 %1</translation>
    </message>
    <message>
        <source>Time from the trigger (s)</source>
        <translation>相对触发时刻的时间（秒）</translation>
    </message>
</context>
<context>
    <name>dd::RunComparison</name>
    <message>
        <source>Rise time (10–90 %)</source>
        <translation>上升时间（10–90 %）</translation>
    </message>
    <message>
        <source>Overshoot</source>
        <translation>超调量</translation>
    </message>
    <message>
        <source>Settling (±2 %)</source>
        <translation>调节时间（±2 %）</translation>
    </message>
    <message>
        <source>Settling (±5 %)</source>
        <translation>调节时间（±5 %）</translation>
    </message>
    <message>
        <source>Steady-state error</source>
        <translation>稳态误差</translation>
    </message>
    <message>
        <source>Steady-state ripple</source>
        <translation>稳态波动</translation>
    </message>
    <message>
        <source>Peak following error</source>
        <translation>最大跟随误差</translation>
    </message>
    <message>
        <source>Peak torque</source>
        <translation>峰值转矩</translation>
    </message>
    <message>
        <source>Peak current</source>
        <translation>峰值电流</translation>
    </message>
    <message>
        <source>Sample interval</source>
        <translation>采样间隔</translation>
    </message>
    <message>
        <source>not resolvable</source>
        <translation>无法分辨</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 毫秒</translation>
    </message>
    <message>
        <source>%1 %2 → %3</source>
        <translation>%1 %2 → %3</translation>
    </message>
    <message>
        <source>no tuning parameter differs</source>
        <translation>调谐参数无差异</translation>
    </message>
    <message>
        <source>%1 → %2: %3: %4</source>
        <translation>%1 → %2：%3：%4</translation>
    </message>
    <message>
        <source>%1, %2: %3</source>
        <translation>%1，%2：%3</translation>
    </message>
    <message>
        <source>Resolution: %1</source>
        <translation>分辨率：%1</translation>
    </message>
    <message>
        <source>Tick runs in the list to compare them here.</source>
        <translation>在列表中勾选运行记录，即可在此比较。</translation>
    </message>
    <message>
        <source>Tick a second run to see the parameter differences.</source>
        <translation>再勾选一条运行记录即可查看参数差异。</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more (the cells&apos; tool tips give every reason).</source>
        <translation>
            <numerusform>…另有 %n 条（每个单元格的提示中给出全部原因）。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 → %2: not comparable: %3</source>
        <translation>%1 → %2：不可比较：%3</translation>
    </message>
</context>
<context>
    <name>dd::RunList</name>
    <message>
        <source>%1 · %2 samples · trigger %3</source>
        <translation>%1 · %2 个样本 · 触发 %3</translation>
    </message>
    <message>
        <source>Not opened: %1</source>
        <translation>未打开：%1</translation>
    </message>
    <message>
        <source>Opened %1.</source>
        <translation>已打开 %1。</translation>
    </message>
    <message>
        <source>Select a run to save.</source>
        <translation>请选择要保存的运行记录。</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>未保存：%1</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>已保存 %1。</translation>
    </message>
    <message>
        <source>Open run</source>
        <translation>打开运行记录</translation>
    </message>
    <message>
        <source>DriveDesk runs (*.ddrun);;All files (*)</source>
        <translation>DriveDesk 运行记录 (*.ddrun);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Save run</source>
        <translation>保存运行记录</translation>
    </message>
    <message>
        <source>DriveDesk runs (*.ddrun)</source>
        <translation>DriveDesk 运行记录 (*.ddrun)</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>打开…</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>保存…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>Tick the runs to overlay; the selected run is the one saved, analysed and applied.</source>
        <translation>勾选要叠加显示的运行记录；保存、分析和应用的对象是选中的那一条。</translation>
    </message>
</context>
<context>
    <name>dd::SpectrumView</name>
    <message>
        <source>Channel:</source>
        <translation>通道：</translation>
    </message>
    <message>
        <source>Frequency (Hz)</source>
        <translation>频率（Hz）</translation>
    </message>
    <message>
        <source>Select a run to see its spectrum.</source>
        <translation>选择一条运行记录以查看其频谱。</translation>
    </message>
    <message>
        <source>No spectrum: %1</source>
        <translation>无频谱：%1</translation>
    </message>
    <message>
        <source>Amplitude of %1</source>
        <translation>%1 的幅值</translation>
    </message>
    <message>
        <source>Amplitude</source>
        <translation>幅值</translation>
    </message>
    <message>
        <source>Peaks:</source>
        <translation>峰值：</translation>
    </message>
    <message>
        <source>%1 Hz (%2)</source>
        <translation>%1 Hz（%2）</translation>
    </message>
    <message>
        <source>Frequency (Hz) · %1 window, resolution %2 Hz, %3 points at %4 Hz, Nyquist %5 Hz</source>
        <translation>频率（Hz）· %1 窗，分辨率 %2 Hz，%3 点，采样率 %4 Hz，奈奎斯特频率 %5 Hz</translation>
    </message>
    <message>
        <source>%1 Hz (%2) — may be an alias of %3 Hz</source>
        <translation>%1 Hz（%2）— 可能是 %3 Hz 的混叠</translation>
    </message>
    <message>
        <source>%1 Hz (%2) — near the Nyquist frequency</source>
        <translation>%1 Hz（%2）— 接近奈奎斯特频率</translation>
    </message>
</context>
<context>
    <name>dd::StepTestControls</name>
    <message>
        <source>maximum speed</source>
        <translation>最高速度</translation>
    </message>
    <message>
        <source>maximum travel</source>
        <translation>最大行程</translation>
    </message>
    <message>
        <source>maximum duration</source>
        <translation>最长时间</translation>
    </message>
    <message>
        <source>Set the limits first: %1.</source>
        <translation>请先设置限值：%1。</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>Give the step a speed above 0.</source>
        <translation>请为阶跃设置大于 0 的速度。</translation>
    </message>
    <message>
        <source>The step&apos;s speed %1 is above the maximum speed %2.</source>
        <translation>阶跃速度 %1 高于最高速度 %2。</translation>
    </message>
    <message>
        <source>Give the position step a distance.</source>
        <translation>请为位置阶跃设置距离。</translation>
    </message>
    <message>
        <source>The distance %1 is beyond the maximum travel %2.</source>
        <translation>距离 %1 超出最大行程 %2。</translation>
    </message>
    <message>
        <source>Give the step a duration.</source>
        <translation>请为阶跃设置持续时间。</translation>
    </message>
    <message>
        <source>The test takes %1 s, longer than the maximum duration %2 s.</source>
        <translation>测试需要 %1 秒，超过最长时间 %2 秒。</translation>
    </message>
    <message>
        <source>Limits (none is assumed)</source>
        <translation>限值（不设默认值）</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>测试</translation>
    </message>
    <message>
        <source>Velocity step</source>
        <translation>速度阶跃</translation>
    </message>
    <message>
        <source>Position step</source>
        <translation>位置阶跃</translation>
    </message>
    <message>
        <source>Reversal (+V, then −V)</source>
        <translation>正反转（先 +V，再 −V）</translation>
    </message>
    <message>
        <source>Max. speed:</source>
        <translation>最高速度：</translation>
    </message>
    <message>
        <source>Max. travel:</source>
        <translation>最大行程：</translation>
    </message>
    <message>
        <source>Max. duration:</source>
        <translation>最长时间：</translation>
    </message>
    <message>
        <source>Test:</source>
        <translation>测试：</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <source>Duration:</source>
        <translation>持续时间：</translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation>距离：</translation>
    </message>
    <message>
        <source>not set</source>
        <translation>未设置</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Stop the test</source>
        <translation>停止测试</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Back to the start afterwards</source>
        <translation>完成后回到起始位置</translation>
    </message>
    <message>
        <source>After a completed test the axis moves back to where it started. An aborted test leaves it where it stopped.</source>
        <translation>测试完成后轴会移回起始位置。中止的测试会让轴停在停止处。</translation>
    </message>
    <message>
        <source>From the start position, in the drive&apos;s position pulses.</source>
        <translation>自起始位置算起，单位为驱动器的位置脉冲数。</translation>
    </message>
</context>
<context>
    <name>dd::TuningParametersEditor</name>
    <message>
        <source>The drive&apos;s dictionary is not known yet.</source>
        <translation>尚未获得驱动器的参数字典。</translation>
    </message>
    <message>
        <source>Edited, not yet written</source>
        <translation>已编辑，尚未写入</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>未读取</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a whole number.</source>
        <translation>“%1”不是整数。</translation>
    </message>
    <message>
        <source>Not taken: %1</source>
        <translation>未采用：%1</translation>
    </message>
    <message>
        <source>Reading the tuning parameters failed: %1</source>
        <translation>读取调谐参数失败：%1</translation>
    </message>
    <message>
        <source>Not written: %1 Nothing was sent.</source>
        <translation>未写入：%1 未向驱动器发送任何内容。</translation>
    </message>
    <message>
        <source>Not applied: %1 Nothing was sent.</source>
        <translation>未应用：%1 未向驱动器发送任何内容。</translation>
    </message>
    <message>
        <source>Not applied: reading the drive failed: %1</source>
        <translation>未应用：读取驱动器失败：%1</translation>
    </message>
    <message numerus="yes">
        <source>%1: the drive already has these %n value(s); nothing written.</source>
        <translation>
            <numerusform>%1：驱动器已是这 %n 个值；未写入任何内容。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n written and read back.</source>
        <translation>
            <numerusform>%n 个已写入并回读校验。</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 applied:</source>
        <translation>已应用 %1：</translation>
    </message>
    <message numerus="yes">
        <source>%n already equal.</source>
        <translation>
            <numerusform>%n 个本已相同。</numerusform>
        </translation>
    </message>
    <message>
        <source>Not verified: %1.</source>
        <translation>未经校验：%1。</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>读取</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>写入</translation>
    </message>
    <message>
        <source>Write the edited values and read them back.</source>
        <translation>写入已编辑的值并回读校验。</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s dictionary…</source>
        <translation>正在读取驱动器的参数字典…</translation>
    </message>
    <message>
        <source>This drive&apos;s dictionary names no tuning parameters. A dictionary with a &quot;tuning&quot; group names them (docs/dictionaries.md).</source>
        <translation>该驱动器的参数字典未列出调谐参数。带有 &quot;tuning&quot; 组的字典可以列出它们（见 docs/dictionaries.md）。</translation>
    </message>
    <message>
        <source>The drive&apos;s dictionary names no tuning parameters: shown are the DriveDesk simulator&apos;s loop gains (its own model). On a real drive these parameters may mean something else.</source>
        <translation>该驱动器的参数字典未列出调谐参数：此处显示的是 DriveDesk 模拟器的环路增益（模拟器自身的模型）。在真实驱动器上，这些参数可能另有含义。</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>未应用：%1</translation>
    </message>
</context>
<context>
    <name>dd::TuningPanel</name>
    <message>
        <source>Step test: reading the drive&apos;s state…</source>
        <translation>阶跃测试：正在读取驱动器状态…</translation>
    </message>
    <message>
        <source>Step test: filling the capture before the motion…</source>
        <translation>阶跃测试：正在填充运动前的采集数据…</translation>
    </message>
    <message>
        <source>Step test: moving…</source>
        <translation>阶跃测试：正在运动…</translation>
    </message>
    <message>
        <source>Step test: stopping…</source>
        <translation>阶跃测试：正在停止…</translation>
    </message>
    <message>
        <source>Step test: running…</source>
        <translation>阶跃测试：正在运行…</translation>
    </message>
    <message>
        <source>Capture stopped: %1</source>
        <translation>捕获已停止：%1</translation>
    </message>
    <message>
        <source>Tuning</source>
        <translation>调谐</translation>
    </message>
    <message>
        <source>This drive reports no live channels to capture.</source>
        <translation>该驱动器没有可捕获的实时通道。</translation>
    </message>
    <message>
        <source>Filling the pre-trigger window…</source>
        <translation>正在填充预触发窗口…</translation>
    </message>
    <message>
        <source>Armed: waiting for the trigger %1.</source>
        <translation>已布防：等待触发 %1。</translation>
    </message>
    <message>
        <source>Triggered: recording…</source>
        <translation>已触发：正在记录…</translation>
    </message>
    <message>
        <source>Capturing…</source>
        <translation>正在捕获…</translation>
    </message>
    <message>
        <source>Captured %1 samples (%2 before the trigger), interval %3 ms.</source>
        <translation>已捕获 %1 个样本（触发前 %2 个），采样间隔 %3 毫秒。</translation>
    </message>
    <message>
        <source>capture %1 · %2</source>
        <translation>捕获 %1 · %2</translation>
    </message>
    <message>
        <source>Not started: stop the free capture first.</source>
        <translation>未启动：请先停止自由捕获。</translation>
    </message>
    <message>
        <source>Not started: %1</source>
        <translation>未启动：%1</translation>
    </message>
    <message>
        <source>Step test done; the axis is back at its start position.</source>
        <translation>阶跃测试完成；轴已回到起始位置。</translation>
    </message>
    <message>
        <source>Step test done; the axis did not return to its start position.</source>
        <translation>阶跃测试完成；轴未回到起始位置。</translation>
    </message>
    <message>
        <source>Step test ended early: %1</source>
        <translation>阶跃测试提前结束：%1</translation>
    </message>
    <message>
        <source>The axis was not seen at rest.</source>
        <translation>未确认轴已静止。</translation>
    </message>
    <message>
        <source>%1 %2 · %3</source>
        <translation>%1 %2 · %3</translation>
    </message>
    <message>
        <source>The tuning parameters could not be read: %1</source>
        <translation>无法读取调谐参数：%1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>Select a run whose parameters to apply.</source>
        <translation>请选择要应用其参数的运行记录。</translation>
    </message>
    <message>
        <source>The selected run holds no tuning parameters.</source>
        <translation>所选运行记录不含调谐参数。</translation>
    </message>
    <message>
        <source>Busy with the drive.</source>
        <translation>正在与驱动器通信。</translation>
    </message>
    <message>
        <source>Reading the drive&apos;s identity…</source>
        <translation>正在读取驱动器信息…</translation>
    </message>
    <message>
        <source>This drive offers no live values to capture: %1</source>
        <translation>该驱动器不提供可捕获的实时值：%1</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>显示：</translation>
    </message>
    <message>
        <source>Runs</source>
        <translation>运行记录</translation>
    </message>
    <message>
        <source>Spectrum</source>
        <translation>频谱</translation>
    </message>
    <message>
        <source>Step test</source>
        <translation>阶跃测试</translation>
    </message>
    <message>
        <source>Capture</source>
        <translation>捕获</translation>
    </message>
    <message>
        <source>Tuning parameters</source>
        <translation>调谐参数</translation>
    </message>
    <message>
        <source>Apply this run&apos;s parameters</source>
        <translation>应用此运行记录的参数</translation>
    </message>
    <message>
        <source>This drive cannot be moved from here: %1</source>
        <translation>无法从此处使该驱动器运动：%1</translation>
    </message>
    <message>
        <source>The drive&apos;s live values are needed for a step test.</source>
        <translation>阶跃测试需要驱动器的实时值。</translation>
    </message>
    <message>
        <source>Step test: the axis moves back to its start position (STOP stops it)…</source>
        <translation>阶跃测试：轴正在返回起始位置（STOP 可停止）…</translation>
    </message>
    <message>
        <source>Step test not started: %1</source>
        <translation>阶跃测试未开始：%1</translation>
    </message>
    <message>
        <source>(aborted: %1)</source>
        <translation>（已中止：%1）</translation>
    </message>
    <message>
        <source>Not started: the power stage is off. DriveDesk does not switch it on by itself: enable it in the Motion tab first.</source>
        <translation>未启动：功率级已关闭。DriveDesk 不会自行开启：请先在“运动”选项卡中使能。</translation>
    </message>
</context>
<context>
    <name>dd::DemoMenu</name>
    <message>
        <source>&amp;Demo</source>
        <translation>演示(&amp;D)</translation>
    </message>
    <message>
        <source>&amp;Inject alarm</source>
        <translation>注入报警(&amp;I)</translation>
    </message>
    <message>
        <source>Start the demo bench first (File → Demo bench)</source>
        <translation>请先启动演示试验台（文件 → 演示试验台）</translation>
    </message>
    <message>
        <source>Alarm %1 on the %2 drive</source>
        <translation>在 %2 驱动器上触发报警 %1</translation>
    </message>
    <message>
        <source>Remove the alarm from the %1 drive</source>
        <translation>解除 %1 驱动器的报警</translation>
    </message>
    <message>
        <source>As when the cause is gone and the drive is reset at its own panel</source>
        <translation>相当于故障原因已排除并在驱动器面板上复位</translation>
    </message>
</context>
<context>
    <name>dd::LoadDictionaryAction</name>
    <message>
        <source>Load &amp;dictionary…</source>
        <translation>加载参数字典(&amp;D)…</translation>
    </message>
    <message>
        <source>Load your drive&apos;s parameter dictionary (names, units, ranges) for the selected drive</source>
        <translation>为所选驱动器加载其参数字典（名称、单位、范围）</translation>
    </message>
</context>
<context>
    <name>dd::DrivePanel</name>
    <message>
        <source>Earlier, at %1: %2</source>
        <translation>此前（%1）：%2</translation>
    </message>
</context>
<context>
    <name>dd::ChannelUnit</name>
    <message>
        <source>r/min</source>
        <translation>r/min</translation>
    </message>
    <message>
        <source>pulse</source>
        <translation>脉冲</translation>
    </message>
    <message>
        <source>pulses</source>
        <translation>脉冲</translation>
    </message>
    <message>
        <source>pulse/s</source>
        <translation>脉冲/秒</translation>
    </message>
    <message>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <source>A</source>
        <translation>A</translation>
    </message>
    <message>
        <source>V</source>
        <translation>V</translation>
    </message>
    <message>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <source>kHz</source>
        <translation>kHz</translation>
    </message>
    <message>
        <source>Hz</source>
        <translation>Hz</translation>
    </message>
    <message>
        <source>pulse/s²</source>
        <translation>脉冲/秒²</translation>
    </message>
    <message>
        <source>1/s</source>
        <translation>1/s</translation>
    </message>
    <message>
        <source>r/min/ms</source>
        <translation>r/min/ms</translation>
    </message>
</context>
<context>
    <name>dd::ModbusReplyMatcher</name>
    <message>
        <source>The reply from address %1 on %2 does not fit the request (%3).</source>
        <translation>%2 上地址 %1 的应答与请求不符（%3）。</translation>
    </message>
    <message>
        <source>The reply from address %1 on %2 failed its CRC. Check the cable shielding, the bus termination and the baud rate.</source>
        <translation>%2 上地址 %1 的应答 CRC 校验失败。请检查电缆屏蔽、总线终端电阻和波特率。</translation>
    </message>
    <message>
        <source>No complete reply from address %1 on %2 within %3 ms: only %4 byte(s) arrived, which form no valid frame (an incomplete or garbled reply). Check the baud rate, the wiring and the bus termination.</source>
        <translation>%3 ms 内 %2 上地址 %1 没有完整应答：只收到 %4 个字节，构不成有效帧（应答不完整或已损坏）。请检查波特率、接线和总线终端电阻。</translation>
    </message>
    <message>
        <source>No reply from address %1 on %2 within %3 ms. Check the drive address (PA51), the baud rate, the wiring (A/B swapped?) and the bus termination.</source>
        <translation>%2 上地址 %1 在 %3 ms 内无应答。请检查驱动器地址（PA51）、波特率、接线（A/B 是否接反？）和总线终端电阻。</translation>
    </message>
    <message>
        <source>A frame with function %1 came from that address instead, which does not answer this request (function %2).</source>
        <translation>该地址发来的是功能码 %1 的帧，不是对本请求（功能码 %2）的应答。</translation>
    </message>
    <message>
        <source>A frame from address %1 arrived instead: do two drives share an address, or does another master talk on the bus?</source>
        <translation>收到的是地址 %1 的帧：是否有两台驱动器使用同一地址，或总线上有另一个主站？</translation>
    </message>
</context>
<context>
    <name>dd::CommandWatch</name>
    <message>
        <source>the drive&apos;s speed command changed from %1 to %2</source>
        <translation>驱动器的速度指令从 %1 变为 %2</translation>
    </message>
    <message>
        <source>the drive reports that it stopped running</source>
        <translation>驱动器报告已停止运行</translation>
    </message>
    <message>
        <source>the drive was disabled</source>
        <translation>驱动器已被禁用</translation>
    </message>
    <message>
        <source>the drive reports the axis at rest</source>
        <translation>驱动器报告轴已静止</translation>
    </message>
</context>
<context>
    <name>dd::StepPlan</name>
    <message>
        <source>The test would take the axis about %1 from the start, including its stop%2: beyond the maximum travel %3.</source>
        <translation>测试将使轴离开起始位置约 %1（含停止过程%2）：超出最大行程 %3。</translation>
    </message>
    <message>
        <source>The test would take the axis about %1 from the start before it even stops%2: beyond the maximum travel %3.</source>
        <translation>测试在开始停止之前就将使轴离开起始位置约 %1%2：超出最大行程 %3。</translation>
    </message>
    <message>
        <source>Shorten the test or lower its speed.</source>
        <translation>请缩短测试或降低速度。</translation>
    </message>
    <message>
        <source>The test needs about %1 s until the axis is at rest, including its stop%2: not within the maximum duration of %3 s.</source>
        <translation>测试需约 %1 s 才能使轴静止（含停止过程%2）：超出最长时间 %3 s。</translation>
    </message>
    <message>
        <source>The test needs about %1 s of motion before it even stops%2: not within the maximum duration of %3 s.</source>
        <translation>测试在开始停止之前就需运动约 %1 s%2：超出最长时间 %3 s。</translation>
    </message>
</context>
<context>
    <name>dd::StopReportView</name>
    <message>
        <source>STOP report</source>
        <translation>停止报告</translation>
    </message>
</context>
<context>
    <name>dd::RunCompatibility</name>
    <message>
        <source>%1 (index %2) is listed twice in the tuning snapshot of %3.</source>
        <translation>%1（索引 %2）在 %3 的调试参数快照中出现了两次。</translation>
    </message>
    <message>
        <source>%1 counts</source>
        <translation>%1 脉冲</translation>
    </message>
    <message>
        <source>%1 r/min</source>
        <translation>%1 r/min</translation>
    </message>
    <message>
        <source>%1 was taken on a %2 drive, %3 on a %4 drive.</source>
        <translation>%1 取自 %2 驱动器，%3 取自 %4 驱动器。</translation>
    </message>
    <message>
        <source>%1 was taken on a %2, %3 on a %4.</source>
        <translation>%1 取自 %2，%3 取自 %4。</translation>
    </message>
    <message>
        <source>The runs were recorded with different dictionaries: index %1 is %2 (%3) in %4 and %5 (%6) in %7.</source>
        <translation>这些运行记录使用了不同的字典：索引 %1 在 %4 中是 %2（%3），在 %7 中是 %5（%6）。</translation>
    </message>
    <message>
        <source>no tuning role</source>
        <translation>无调试角色</translation>
    </message>
    <message>
        <source>%1 is a %2, %3 a %4: different tests do not compare.</source>
        <translation>%1 是 %2，%3 是 %4：不同的测试不可比较。</translation>
    </message>
    <message>
        <source>%1 and %2 are steps of different sizes (%3, %4): their metrics do not compare.</source>
        <translation>%1 和 %2 是幅度不同的阶跃（%3，%4）：它们的指标不可比较。</translation>
    </message>
</context>
<context>
    <name>dd::JournalKey</name>
    <message>
        <source>machine “%1”</source>
        <translation>机器“%1”</translation>
    </message>
    <message>
        <source>%1 address %2 on %3</source>
        <translation>%3 上地址 %2 的 %1</translation>
    </message>
    <message>
        <source>an unnamed link</source>
        <translation>未命名的连接</translation>
    </message>
    <message>
        <source>firmware %1</source>
        <translation>固件 %1</translation>
    </message>
    <message>
        <source>model %1</source>
        <translation>型号 %1</translation>
    </message>
    <message>
        <source>Identified by %1.</source>
        <translation>识别依据：%1。</translation>
    </message>
    <message>
        <source>link</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>address</source>
        <translation>地址</translation>
    </message>
    <message>
        <source>firmware</source>
        <translation>固件</translation>
    </message>
    <message>
        <source>model</source>
        <translation>型号</translation>
    </message>
    <message>
        <source>This family reports no serial number: two drives with the same %1 cannot be told apart.</source>
        <translation>该系列驱动器不报告序列号：%1均相同的两台驱动器无法区分。</translation>
    </message>
    <message>
        <source>%1 and %2</source>
        <translation>%1和%2</translation>
    </message>
    <message>
        <source>The drive reported no firmware version.</source>
        <translation>驱动器未报告固件版本。</translation>
    </message>
    <message>
        <source>No machine name was set: drives of different machines reached the same way share one journal.</source>
        <translation>未设置机器名称：以相同方式连接的不同机器上的驱动器共用一份校验日志。</translation>
    </message>
</context>
</TS>
