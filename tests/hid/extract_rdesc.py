# SPDX-License-Identifier: MIT
import re,sys
# Extracts report_descriptor = [...] of a hid-tools device class as hex lines:
# python3 extract_rdesc.py hidtools/device/sony_gamepad.py PS4ControllerUSB
# usage: extract_rdesc.py FILE CLASSNAME  -> prints hex of the class's report_descriptor list
src=open(sys.argv[1]).read()
i=src.index("class %s("%sys.argv[2])
j=src.index("report_descriptor = [",i)
k=src.index("\n    ]",j)
body=src[j:k]
out=[]
for line in body.split("\n")[1:]:
    code=line.split("#")[0]
    out+= [int(x,16) for x in re.findall(r"0x([0-9a-fA-F]{2})",code)]
print(len(out),file=sys.stderr)
for n in range(0,len(out),16):
    print(" ".join("%02x"%b for b in out[n:n+16]))
