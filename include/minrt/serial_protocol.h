/* What travels over the serial link between a host and the min-rt firmware.
 * Shared by the firmware (runtime/) and the host tools that talk to it
 * (host-send). Plain C so both sides, and C test code, can include it.
 *
 * Host -> firmware: the SLD scene as plain bytes, nothing around it. The
 *   firmware stops reading after the scene's final terminator, so a valid
 *   scene needs no end marker. For an incomplete scene the firmware needs
 *   to learn that nothing more will come; either
 *     - the sender appends MINRT_END_OF_INPUT (a byte no SLD text contains), or
 *     - the line stays idle for MINRT_IDLE_POLLS_DEFAULT consecutive UART
 *       status polls with no byte (firmware-sim gives up on a firmware that
 *       polls an exhausted input 2,000,000 times, so this must stay below).
 *   Either way the reader sees end of input and reports the scene as
 *   truncated.
 *
 * Firmware -> host: exactly one of
 *   - the PPM image (starts with 'P'), streamed row by row, or
 *   - one text line: MINRT_ERROR_MARKER, then "LINE:COL: message" for a scene
 *     error or just "message" for anything else, then '\n'. Nothing else
 *     follows.
 *   With boot arguments the machine then halts with one of the
 *   MINRT_STATUS_* codes (through the test finisher, so a simulator or QEMU
 *   exits with it); a board without any waits for the next scene instead
 *   (unless its board file says after_image = halt; the session below).
 *   A host that asks for it first (MINRT_CHECK_REQUEST, below) gets the
 *   image between an announce byte and a CRC-32 trailer.
 */
#ifndef MINRT_SERIAL_PROTOCOL_H
#define MINRT_SERIAL_PROTOCOL_H

/* '!' cannot begin a PPM (which begins with 'P'). */
#define MINRT_ERROR_MARKER "!minrt-error: "

/* CS418 scenes with textures (raw protocol): the textures travel ahead of
 * the scene text, decoded on the host:
 *   MINRT_TEXTURES_MARKER, count (1 byte, 1..MINRT_MAX_TEXTURES), then for each
 *   texture: name length (1 byte, 1..255), the name as written in the scene,
 *   width and height (2 bytes each, little-endian, 1..MINRT_MAX_TEXTURE_SIDE),
 *   width*height*3 bytes of sRGB RGB, top row first;
 * then the scene text as usual. The firmware answers with a PNG stream
 * (starts with 0x89) or the error line. */
#define MINRT_TEXTURES_MARKER 0x01
#define MINRT_MAX_TEXTURES 64
#define MINRT_MAX_TEXTURE_SIDE 16384

/* The same textures compressed, as host-send sends them (every protocol):
 *   MINRT_TEXTURES_DEFLATE_MARKER, count (1 byte), the lead (4 bytes LE,
 *   below), then for each texture: name length and name, width and height
 *   as above, the compressed size and the CRC-32 of the width*height*3
 *   decoded texel bytes (4 bytes LE each), then that many bytes: a raw
 *   deflate stream (RFC 1951) of the texels filtered as
 *   protocol/texel_filter.hpp says.
 * A board that holds the upload whole decodes the textures where it lies:
 * the texels of all textures, one after the other, start `lead` bytes
 * below the marker and end inside the compressed bytes. The host makes
 * lead the most the texels written ever run ahead of the bytes read (both
 * counted from the marker), so no texel overwrites a byte still to be read;
 * the board's inflater checks that too (core/base/inflate.hpp). */
#define MINRT_TEXTURES_DEFLATE_MARKER 0x06 /* ASCII ACK: no scene format starts with it */

/* Sparse textures, host-send's default for CS418 scenes: the compressed
 * preamble's layout under its own marker, each texture's header followed by
 * its form (1 byte) and the count of texels sent (4 bytes LE):
 *   form 0: every texel, the stream as above (sent = width*height);
 *   form k in 1..MINRT_TEXTURES_MAX_TILE_FORM: the texels of some tiles of
 *   2^(k-1) x 2^(k-1) texels (the last row and column of tiles cut at the
 *   edges). The stream decodes to the tile mask (one bit a tile, rows of
 *   tiles top first, least significant bit first, ceil(tiles/8) bytes), then
 *   the `sent` texels of the marked tiles, row by row, filtered as
 *   protocol/texel_filter.hpp's sparse form says.
 * The texels not sent read as MINRT_TEXTURES_UNSENT_RGB, and the CRC-32 is
 * that of the whole texture so filled. The host sends the tiles its own
 * render of the scene read; a board that reads any other texel stops with
 * MINRT_UNSENT_TEXEL_ERROR in its error line, and host-send sends the
 * textures whole instead. No texture is decoded in place: lead is 0. */
#define MINRT_TEXTURES_SPARSE_MARKER 0x07 /* ASCII BEL: no scene format starts with it */
#define MINRT_TEXTURES_MAX_TILE_FORM 8
#define MINRT_TEXTURES_UNSENT_RGB {0xFF, 0x00, 0xFF}
#define MINRT_UNSENT_TEXEL_ERROR "texel not sent: "

/* Raw protocol, CRC-32 trailer (host-send asks for it unless --no-check).
 *   Host -> board: MINRT_CHECK_REQUEST as the very first byte, before the
 *   textures marker or the scene.
 *   Board -> host, when it was asked and has an image to send:
 *   MINRT_CHECK_ANNOUNCE, the image exactly as without the request, then
 *   the trailer of MINRT_CHECK_TRAILER_SIZE bytes: MINRT_CHECK_TRAILER_MAGIC
 *   (4 bytes), the image's byte count and its CRC-32/IEEE (core/base/crc32.hpp),
 *   each 4 bytes little-endian. The announce byte and the trailer are not
 *   part of the image or of the CRC. An error line is sent as always, with
 *   neither. Without the request the reply is byte for byte what it was (and
 *   what minrt prints), so a terminal or an older host sees a plain image.
 *   The course and framed protocols do not use this: the course defines its
 *   own bytes, and framed has a CRC on every frame. */
#define MINRT_CHECK_REQUEST 0x02 /* ASCII STX: no scene format starts with it */
#define MINRT_CHECK_ANNOUNCE 0x02
#define MINRT_CHECK_TRAILER_MAGIC "\003CRC" /* ETX, then "CRC" */
#define MINRT_CHECK_TRAILER_SIZE 12

/* Raw protocol, checked upload (host-send's default): MINRT_SCENE_CHECK_REQUEST
 * as the very first byte, then the upload's byte count and CRC-32 (4 bytes
 * each, little-endian), then the bytes (texture preamble and scene text; no
 * end-of-input byte). The board holds the upload whole, refuses it with an
 * error line when the CRC-32 differs, and answers as to MINRT_CHECK_REQUEST
 * (announce byte, image, trailer). protocol/scene_check.hpp has both ends and
 * the course protocol's form. */
#define MINRT_SCENE_CHECK_REQUEST 0x05 /* ASCII ENQ: no scene format starts with it */

/* ASCII EOT (Ctrl-D): optional end-of-input byte after the scene. */
#define MINRT_END_OF_INPUT 0x04

/* Empty UART status polls after which the firmware takes the input as ended. */
#define MINRT_IDLE_POLLS_DEFAULT 1000000

/* The framed protocol ends explicitly (E after the scene, F after the
 * image), so silence there means a slow or damaged line, or a lost host:
 * the firmware allows this many times the idle polls before giving up
 * (saturating; 0 still waits forever). At the default that is about 1e9
 * polls: a minute or more on a 100 MHz board, longer than host-send's
 * longest retry interval (30 s); far longer in firmware-sim, which waits for
 * its host between polls. A host that goes away closes the line, and that
 * ends the input at once. */
#define MINRT_FRAMED_IDLE_FACTOR 1024

/* The scene formats travel by the tag the registry gives each one
 * (formats/registry.hpp, Format::wire_tag). Raw tells them apart by content;
 * course and framed carry SLD (tag MINRT_SCENE_FORMAT_SLD) as they always did
 * and the other formats behind a header with their tag
 * (protocol/text_scene_upload.hpp). Tags are fixed: boards and hosts of
 * different versions must agree. */
#define MINRT_SCENE_FORMAT_SLD 0
#define MINRT_SCENE_FORMAT_TAG_LIMIT 256 /* tags are below it */

/* Session (host-send's handshake, protocol/session.hpp has both ends and
 * the whole exchange). A board that got no boot arguments waits for the
 * host for as long as it takes, and between scenes takes:
 *   MINRT_SESSION_GREETING  -> the board answers with its identity line
 *   MINRT_SESSION_OPTIONS   -> the run's options line; the board answers
 *                              MINRT_SESSION_ACCEPTED (or an error line), then
 *                              the chosen protocol runs as it does alone
 *   any other first byte    -> raw, course or framed as before, with the
 *                              board's build-time defaults
 * Every session message starts with MINRT_SESSION_LEAD (ASCII SYN), which no
 * scene format, course word stream (the host's first word is a program
 * length) or framed frame (0xA5 0x5A) begins with. Lines are text, fields
 * `key=value` separated by one space, ending in ` crc=XXXXXXXX` (CRC-32/IEEE
 * of the bytes after the lead up to the space before `crc`, 8 lower-case
 * hex digits) and '\n'. */
#define MINRT_SESSION_LEAD 0x16 /* ASCII SYN */
#define MINRT_SESSION_GREETING "\026mrt?"  /* SYN m r t ? */
#define MINRT_SESSION_GREETING_SIZE 5
#define MINRT_SESSION_IDENTITY "\026minrt-board" /* SYN, then the identity's fields */
#define MINRT_SESSION_OPTIONS "\026o"              /* SYN o, then the options' fields */
#define MINRT_SESSION_ACCEPTED "\026ok\n"
#define MINRT_SESSION_VERSION 1
#define MINRT_SESSION_LINE_MAX 480 /* bytes of a session line, lead to '\n' */

/* Halt status. */
#define MINRT_STATUS_OK 0
#define MINRT_STATUS_USAGE 2         /* bad firmware arguments (like `minrt`) */
#define MINRT_STATUS_SCENE_ERROR 2   /* the SLD input was rejected */
#define MINRT_STATUS_OUT_OF_MEMORY 3 /* the scene does not fit the arena */
#define MINRT_STATUS_TRAP 4          /* unexpected CPU exception */
#define MINRT_STATUS_BAD_PROGRAM 8   /* course boot stage: the uploaded program is
                                        larger than the program region (memory_map.h)
                                        or ended early */

#endif
