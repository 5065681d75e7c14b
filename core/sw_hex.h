/* SPDX-License-Identifier: MIT */
/* Hexadecimal digits, for the text formats that carry bytes as hex (pack
 * keys and signatures, SDL mapping GUIDs, recorded HID reports). */
#ifndef SW_HEX_H
#define SW_HEX_H

/* The value of one hex digit, either case; -1 for any other character. */
int sw_hex_digit(char c);

#endif
