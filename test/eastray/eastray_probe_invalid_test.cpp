// EASTRAY invalid inputs beyond ../shared and test/eastray/eastray_bad:
// each class of invalid input in new forms, plus the lexical and
// preprocessor corner cases (unterminated comments and include names,
// include cycles through three files, self-referring and exploding macros,
// bad number spellings, empty files, binary garbage, huge tokens, deep
// nesting). Each must give one `file:line:col: error: ...` line, a non-zero
// status and no image, from minrt and from host-send (refused before any
// link is opened, whatever the protocol).
#include "eastray_probe_support.hpp"

#include <algorithm>

using namespace eprobe;

namespace {

// 6 lines; the objects start on line 7.
const char* kHead =
    "display 32 24 0 0 31 23 1 1 1 ;\ncondition 4 0.01 0.00001 0 ;\ncamera 0 2 9  0 1 0  0 10 0  25 0 ;\n"
    "sky 0.2 0.4 0.8 ;\nenv 0.2 0.2 0.2 ;\ncolor [ grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ; ]\n";

struct Case {
  std::string name;
  std::string text;
  std::string where;    // what the line starts with: FILE:LINE:COL:
  std::string message;  // a part of the message
};

std::vector<Case> cases() {
  const std::string h = kHead;
  const std::string tri = "p 0 0 0 0  p 1 1 0 0  p 2 0 1 0  ";
  std::vector<Case> c = {
      // comments and the preprocessor
      {"comment-open-at-end", h + "obj [ 2 grey 1  0 1 0  1 ; ]\n/* never closed\n", "comment-open-at-end.ray:8:1:",
       "unterminated comment"},
      {"comment-second-open", h + "obj [ 2 grey 1  0 1 0  1 ; /* a */ /* b\n ]\n", "comment-second-open.ray:7:36:",
       "unterminated comment"},
      {"comment-in-define", "#define X /* \n" + h + "obj [ ]\n", "comment-in-define.ray:1:11:", "unterminated comment"},
      {"include-open-quote", h + "#include \"colors.h\nobj [ ]\n", "include-open-quote.ray:7:10:", "no closing \""},
      {"include-open-angle", h + "#include <colors.h\nobj [ ]\n", "include-open-angle.ray:7:10:", "no closing >"},
      {"include-no-name", h + "#include\nobj [ ]\n", "include-no-name.ray:7:", "#include needs"},
      {"include-missing", h + "obj [\n#include \"nowhere/none.h\"\n]\n", "include-missing.ray:8:10:", "none.h"},
      {"unknown-directive", h + "#ifdef X\nobj [ ]\n", "unknown-directive.ray:7:", "ifdef"},
      {"macro-self", h + "#define R R 1\nobj [ 2 grey 1  0 1 0  R ; ]\n", "macro-self.ray:8:24:", "expected a number"},
      {"macro-mutual", h + "#define A B\n#define B A\nobj [ 2 grey 1  0 1 0  A ; ]\n", "macro-mutual.ray:9:24:",
       "expected a number"},
      // parts
      {"part-twice", h + "obj [ p ; ]\nobj p [ 2 grey 1  0 1 0  1 ; ]\nobj p [ 2 grey 1  0 1 0  2 ; ]\n", "part-twice.ray:9:5:",
       "part defined twice"},
      {"parts-no-main", h + "obj a [ b ; ]\nobj b [ 2 grey 1  0 1 0  1 ; ]\n", "parts-no-main.ray:9:1:", "no main object"},
      {"cycle-of-3", h + "obj [ a ; ]\nobj a [ b ; ]\nobj b [ c ; ]\nobj c [ 2 grey 1 0 1 0 1 ; a ; ]\n", "cycle-of-3.ray:10:28:",
       "recursive call of part 'a'"},
      {"uncalled-cycle", h + "obj [ 2 grey 1 0 1 0 1 ; ]\nobj a [ b ; ]\nobj b [ a ; ]\n", "uncalled-cycle.ray:9:9:",
       "recursive call"},
      {"call-without-semicolon", h + "obj [ p ]\nobj p [ 2 grey 1  0 1 0  1 ; ]\n", "call-without-semicolon.ray:7:9:",
       "expected ';'"},
      // RANGE
      {"range-kind-9", h + "obj [ ( 9  0 1 0  1 ; 2 grey 1  0 1 0  0.5 ; ) ]\n", "range-kind-9.ray:7:9:", "kind 0 to 8, found kind 9"},
      {"range-kind-17", h + "obj [ ( 17  0 1 0  1 ; 2 grey 1  0 1 0  0.5 ; ) ]\n", "range-kind-17.ray:7:9:", "found kind 17"},
      {"range-kind-20", h + "obj [ ( 20 < " + tri + "P 0 1 2 ; > ; 2 grey 1  0 1 0  0.5 ; ) ]\n", "range-kind-20.ray:7:9:",
       "found kind 20"},
      {"range-kind-15", h + "obj [ { ( 15  0 1 0  0 1 0  1 1 ; 2 grey 1  0 1 0  0.5 ; ) } ]\n", "range-kind-15.ray:7:11:",
       "found kind 15"},
      // polygons
      {"vertex-negative-in-face", h + "obj [ 20 grey 1 < " + tri + "P 0 1 -2 ; > ; ]\n", "vertex-negative-in-face.ray:7:58:",
       "vertex number of the face"},
      {"vertex-negative-id", h + "obj [ 20 grey 1 < p -1 0 0 0  p 1 1 0 0  p 2 0 1 0  P -1 1 2 ; > ; ]\n",
       "vertex-negative-id.ray:7:21:", "vertex number"},
      {"vertex-huge", h + "obj [ 20 grey 1 < " + tri + "P 0 1 99999999999 ; > ; ]\n", "vertex-huge.ray:7:58:", "whole number"},
      {"vertex-fraction", h + "obj [ 20 grey 1 < " + tri + "P 0 1 2.5 ; > ; ]\n", "vertex-fraction.ray:7:58:", "whole number"},
      {"vertex-undefined-last", h + "obj [ 20 grey 1 < " + tri + "P 0 1 2 ;\n  P 2 1 3 ; > ; ]\n", "vertex-undefined-last.ray:8:",
       "undefined vertex 3"},
      {"vertex-after-face", h + "obj [ 20 grey 1 < " + tri + "P 0 1 2 ;  p 3 1 1 0 > ; ]\n", "vertex-after-face.ray:7:63:",
       "must all come before the faces"},
      {"face-two-vertices", h + "obj [ 20 grey 1 < " + tri + "P 0 1 ; > ; ]\n", "face-two-vertices.ray:7:", "at least 3 vertices"},
      {"polygon-unterminated", h + "obj [ 20 grey 1 < " + tri + "P 0 1 2 ;\n ; ]\n", "polygon-unterminated.ray:8:2:",
       "in the polygon"},
      // numbers
      {"number-1e", h + "obj [ 2 grey 1  0 1 0  1e ; ]\n", "number-1e.ray:7:24:", "expected a number"},
      {"number-1e+", h + "obj [ 2 grey 1  0 1 0  1e+ ; ]\n", "number-1e+.ray:7:24:", "expected a number"},
      {"number-minus-minus", h + "obj [ 2 grey 1  0 1 0  --1 ; ]\n", "number-minus-minus.ray:7:24:", "expected a number"},
      {"number-dot", h + "obj [ 2 grey 1  0 1 0  . ; ]\n", "number-dot.ray:7:24:", "expected a number"},
      {"number-plus", h + "obj [ 2 grey 1  0 1 0  + ; ]\n", "number-plus.ray:7:24:", "expected a number"},
      {"number-two-points", h + "obj [ 2 grey 1  0 1 0  1.2.3 ; ]\n", "number-two-points.ray:7:24:", "expected a number"},
      {"number-hex", h + "obj [ 2 grey 1  0 1 0  0x10 ; ]\n", "number-hex.ray:7:24:", "expected a number"},
      {"number-huge-exponent", h + "obj [ 2 grey 1  0 1 0  1e99999 ; ]\n", "number-huge-exponent.ray:7:24:", "out of range"},
      {"number-huge-negative", h + "obj [ 2 grey 1  -1e400 1 0  1 ; ]\n", "number-huge-negative.ray:7:17:", "out of range"},
      {"number-tiny-radius", h + "obj [ 2 grey 1  0 1 0  1e-99999 ; ]\n", "number-tiny-radius.ray:7:7:", "radius must be above 0"},
      {"number-nan", h + "obj [ 2 grey 1  0 1 0  NaN ; ]\n", "number-nan.ray:7:24:", "expected a number"},
      {"number-inf", h + "obj [ 2 grey 1  0 1 0  inf ; ]\n", "number-inf.ray:7:24:", "expected a number"},
      {"number-minus-infinity", h + "obj [ 2 grey 1  0 1 0  -Infinity ; ]\n", "number-minus-infinity.ray:7:24:", "expected a number"},
      {"number-fullwidth", h + "obj [ 2 grey 1  0 1 0  \xef\xbc\x91 ; ]\n", "number-fullwidth.ray:7:24:", "expected a number"},
      {"number-300-digits", h + "obj [ 2 grey 1  0 1 0  0." + std::string(300, '3') + " ; ]\n", "number-300-digits.ray:7:24:",
       "too many digits"},
      // signs and kinds
      {"sign-zero", h + "obj [ 2 grey 0  0 1 0  1 ; ]\n", "sign-zero.ray:7:14:", "sign must be 1 or -1"},
      {"sign-two", h + "obj [ { 16 grey 2  0 1 0  1 1 1 ; } ]\n", "sign-two.ray:7:17:", "sign must be 1 or -1, found '2'"},
      {"sign-polygon", h + "obj [ 20 grey 0.5 < " + tri + "P 0 1 2 ; > ; ]\n", "sign-polygon.ray:7:15:", "sign must be 1 or -1"},
      {"kind-9", h + "obj [ 9 grey 1  0 1 0  1 ; ]\n", "kind-9.ray:7:7:", "unknown object kind 9"},
      {"kind-minus-4", h + "obj [ -4 grey 1  0 1 0  1 ; ]\n", "kind-minus-4.ray:7:7:", "object kind"},
      // blocks
      {"main-unterminated", h + "obj [ 2 grey 1  0 1 0  1 ;", "main-unterminated.ray:7:", "unterminated block"},
      {"and-unterminated", h + "obj [ 2 grey 1  0 1 0  1 ;\n { [ 2 grey 1  0 1 0  1 ; ]\n", "and-unterminated.ray:8:2:",
       "unterminated block"},
      {"range-closed-by-bracket", h + "obj [ ( 2 0 1 0 2 ; 2 grey 1  0 1 0  1 ;\n]\n", "range-closed-by-bracket.ray:8:1:", "found ']'"},
      {"and-closed-by-bracket", h + "obj [ { 2 grey 1  0 1 0  1 ; ] }\n", "and-closed-by-bracket.ray:7:30:", "found ']'"},
      {"one-close-too-many", h + "obj [ 2 grey 1  0 1 0  1 ; ] ]\n", "one-close-too-many.ray:7:30:", "unknown statement ']'"},
      {"deep-nesting", h + "obj [ " + [] {
         std::string s;
         for (int i = 0; i < 100000; ++i) s += "[ ";
         return s;
       }() + "\n",
       "deep-nesting.ray:7:", "nested too deeply"},
      {"deep-nesting-33", h + "obj [ " + [] {
         std::string s;
         for (int i = 0; i < 33; ++i) s += "{ ";
         s += "2 grey 1 0 1 0 1 ; ";
         for (int i = 0; i < 33; ++i) s += "} ";
         return s;
       }() + "]\n",
       "deep-nesting-33.ray:7:", "nested too deeply"},
      // statements
      {"unknown-move", h + "obj [ :mw 1 2 grey 1  0 1 0  1 ; ]\n", "unknown-move.ray:7:7:", "unknown move command ':mw'"},
      {"mtx-short", h + "obj [ :mtx 1 0 0 0  0 1 0 0  0 0 1 0 2 grey 1  0 1 0  1 ; ]\n", "mtx-short.ray:7:40:", ":mtx element"},
      {"colour-list-open", "display 32 24 0 0 31 23 1 1 1 ;\ncolor [ grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
                           "obj [ 2 grey 1  0 1 0  1 ; ]\n",
       "colour-list-open.ray:3:5:", "expected a number"},
      {"light-list-open", h + "e_light [ 0 1 0  1 1 1  0 1 ;\nobj [ 2 grey 1  0 1 0  1 ; ]\n", "light-list-open.ray:8:1:",
       "e_light direction"},
      {"ior-zero-glass", "color [ g 0 0 0  1 1 1  0 0.5 0  0 1  0  0 0 1 ; ]\nobj [ 2 g 1  0 1 0  1 ; ]\n", "ior-zero-glass.ray:1:34:",
       "index of refraction of a transparent colour must be above 0"},
      {"ior-negative-glass", "color [ g 0 0 0  1 1 1  1 1 1  -1.5 1  0  0 0 1 ; ]\nobj [ 2 g 1  0 1 0  1 ; ]\n",
       "ior-negative-glass.ray:1:32:", "must be above 0"},
      {"colour-number-undefined", h + "obj [ 2 7 1  0 1 0  1 ; ]\n", "colour-number-undefined.ray:7:9:", "undefined colour number 7"},
      {"display-too-wide", "display 4096 24 0 0 31 23 1 1 1 ;\nobj [ ]\n", "display-too-wide.ray:1:9:", "display width"},
      {"display-step-zero", "display 32 24 0 0 31 23 0 1 1 ;\nobj [ ]\n", "display-step-zero.ray:1:25:", "display step"},
      {"condition-negative", "condition -1 0.01 0.00001 0 ;\nobj [ ]\n", "condition-negative.ray:1:11:", "condition depth"},
      // the manual sets no height or depth limit (lines 72, 89): ours are named
      {"display-too-high", "display 32 16385 0 0 31 23 1 1 1 ;\nobj [ ]\n", "display-too-high.ray:1:12:",
       "display height 16385 is above 16384, the most this program renders"},
      {"condition-too-deep", "condition 17 0.01 0.00001 0 ;\nobj [ ]\n", "condition-too-deep.ray:1:11:",
       "condition depth 17 is above 16, the most this program traces"},
      // switches: the manual's explanations know 1 and 0 only (lines 92, 128, 249)
      {"shadow-two", h + "shadow 2 ;\nobj [ 2 grey 1  0 1 0  1 ; ]\n", "shadow-two.ray:7:8:",
       "shadow switch must be 0 or 1, found '2'"},
      {"shadow-minus-one", h + "shadow -1\nobj [ 2 grey 1  0 1 0  1 ; ]\n", "shadow-minus-one.ray:7:8:",
       "shadow switch must be 0 or 1, found '-1'"},
      {"shadow-half", h + "shadow 0.5 ;\nobj [ 2 grey 1  0 1 0  1 ; ]\n", "shadow-half.ray:7:8:",
       "shadow switch must be 0 or 1, found '0.5'"},
      {"shadow-on", h + "shadow on ;\nobj [ 2 grey 1  0 1 0  1 ; ]\n", "shadow-on.ray:7:8:", "expected a number (shadow switch)"},
      {"mist-switch-two", h + "mist 20 2 ;\nobj [ 2 grey 1  0 1 0  1 ; ]\n", "mist-switch-two.ray:7:9:",
       "mist switch must be 0 or 1, found '2'"},
      {"condition-inner-two", "condition 4 0.01 0.00001 2 ;\nobj [ 2 grey 1  0 1 0  1 ; ]\n", "condition-inner-two.ray:1:26:",
       "condition inner switch must be 0 or 1, found '2'"},
      {"condition-inner-minus", "condition 4 0.01 0.00001 -1 ;\nobj [ 2 grey 1  0 1 0  1 ; ]\n",
       "condition-inner-minus.ray:1:26:", "condition inner switch must be 0 or 1, found '-1'"},
      // whole files
      {"empty", "", "empty.ray:1:1:", "no main object"},
      {"only-a-comment", "/* nothing */\n", "only-a-comment.ray:2:1:", "no main object"},
      // the end of a file without a final newline is on its last line,
      // just past its last character (also where a Ctrl-Z ends the text)
      {"no-final-newline", "display 32 24 0 0 31 23 1 1 1 ", "no-final-newline.ray:1:31:",
       "expected ';' to end 'display', found the end of the scene"},
      {"no-final-newline-8", h + "obj [ 2 grey 1  0 1 0  1 ; ]\nshadow", "no-final-newline-8.ray:8:7:",
       "expected a number (shadow switch), found the end of the scene"},
      {"ctrl-z-mid-line", "display 32 24 0 0 31 23 1 1 1\x1a ;\n", "ctrl-z-mid-line.ray:1:30:", "expected ';' to end 'display'"},
      {"nul-byte", std::string("display 32 24 0 0 31 23 1 1 1 \0 ;\n", 34), "nul-byte.ray:1:31:", "expected ';'"},
      {"long-name", h + "obj [ 2 grey 1  0 1 0  1 ; ]\n" + std::string(3000000, 'a') + "\n", "long-name.ray:8:1:",
       "unknown statement 'aaaa"},
      {"long-line", h + "obj [ " + [] {
         std::string s;
         for (int i = 0; i < 100000; ++i) s += "2 grey 1 0 1 0 0.1 ; ";
         return s;
       }() + "zz ; ]\n",
       "long-line.ray:7:2100007:", "undefined part 'zz'"},
  };
  // Parts calling the next part twice, 30 deep: 2^30 placements.
  std::string tree = h + "obj [ p0 ; ]\n";
  for (int i = 0; i < 30; ++i)
    tree += "obj p" + std::to_string(i) + " [ p" + std::to_string(i + 1) + " ; :mx 0.001 p" + std::to_string(i + 1) + " ; ]\n";
  // The arena grows with the objects placed, so the part-call bound stops it.
  c.push_back({"part-tree-of-spheres", tree + "obj p30 [ 2 grey 1  0 0 0  0.1 ; ]\n", "part-tree-of-spheres.ray:",
               "too many part calls placed"});
  c.push_back({"part-tree-of-nothing", tree + "obj p30 [ ]\n", "part-tree-of-nothing.ray:", "too many part calls placed"});
  // Bytes 0x80-0xff and controls, deterministic.
  std::string garbage;
  uint32_t x = 12345;
  for (int i = 0; i < 4000; ++i) {
    x = x * 1103515245u + 12345u;
    garbage += static_cast<char>(0x80 | (x >> 24));
  }
  c.push_back({"binary-garbage", garbage, "binary-garbage.ray:1:1:", "unknown statement"});
  return c;
}

}  // namespace

TEST_CASE("eastray probe: invalid inputs get one located error line, status 2, no image", "[eastray][eprobe]") {
  const std::string dir = temp_dir();
  // Three files including each other in a ring, and a header for the <...> case.
  write(dir + "/ring1.h", "/* one */\n#include \"ring2.h\"\n");
  write(dir + "/ring2.h", "\n\n#include \"ring3.h\"\n");
  write(dir + "/ring3.h", "#include \"ring1.h\"\n");
  // A chain of 70 includes, each a file of its own.
  for (int i = 0; i < 70; ++i) write(dir + "/f" + std::to_string(i) + ".h", "#include \"f" + std::to_string(i + 1) + ".h\"\n");
  write(dir + "/f70.h", "2 grey 1  0 1 0  1 ;\n");
  std::vector<Case> all = cases();
  all.push_back({"include-70-deep", std::string(kHead) + "obj [\n#include \"f0.h\"\n]\n", "f63.h:1:10:",
                 "#include nested deeper than 64"});
  all.push_back({"include-ring", std::string(kHead) + "#include \"ring1.h\"\nobj [ ]\n", "ring3.h:1:10:", "#include cycle"});
  // The scene ends after an include: its end is the scene file's, not the
  // line after the included file's last.
  write(dir + "/tail3.h", "\n\n\n");
  all.push_back({"include-at-end", std::string(kHead) + "obj [ 2 grey 1  0 1 0  1 ; ]\nshadow\n#include \"tail3.h\"\n",
                 "include-at-end.ray:10:1:", "expected a number (shadow switch), found the end of the scene"});
  all.push_back({"include-at-end-no-newline", std::string(kHead) + "obj [ 2 grey 1  0 1 0  1 ; ]\nshadow\n#include \"tail3.h\"",
                 "include-at-end-no-newline.ray:9:19:", "expected a number (shadow switch), found the end of the scene"});
  all.push_back({"include-angle-missing", std::string(kHead) + "#include <nothere.h>\nobj [ ]\n", "include-angle-missing.ray:7:10:",
                 "nothere.h"});
  for (const Case& c : all) {
    INFO(c.name);
    const std::string file = c.name + ".ray";
    write(dir + "/" + file, c.text);
    const std::string out = dir + "/" + c.name + ".png";
    const Run r = run("EASTRAY='" + dir + "/sys' " + std::string(MINRT_BIN) + " -o " + out + " " + file, dir);
    INFO(r.err.substr(0, 400));
    CHECK(r.status == 2);
    CHECK(r.err.rfind(c.where, 0) == 0);
    CHECK(r.err.find(": error: ") != std::string::npos);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.size() < 400);  // long tokens are shortened in the message
    CHECK_FALSE(exists(out));
    // The default name (the scene's name with .png) is not written either.
    CHECK_FALSE(exists(dir + "/" + c.name + ".png"));
  }
}

TEST_CASE("eastray probe: host-send refuses invalid inputs before sending, over every protocol", "[eastray][eprobe]") {
  const std::string dir = temp_dir();
  // One of each class; host-send reads with the board's reader.
  const char* names[] = {"comment-second-open", "include-open-quote", "macro-mutual", "part-twice", "parts-no-main",
                         "cycle-of-3", "range-kind-20", "vertex-negative-in-face", "number-1e", "number-300-digits",
                         "sign-two", "deep-nesting-33", "empty", "binary-garbage"};
  const std::vector<Case> all = cases();
  for (const char* n : names) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const Case& c) { return c.name == n; });
    REQUIRE(it != all.end());
    const std::string file = it->name + ".ray";
    write(dir + "/" + file, it->text);
    for (const char* protocol : {"raw", "course", "framed"}) {
      INFO(n << " over " << protocol);
      const std::string out = dir + "/out.png";
      const Run r = run(std::string(MINRT_SEND_BIN) + " --sim --protocol " + protocol + " " + file + " -o " + out, dir);
      INFO(r.err.substr(0, 400));
      CHECK(r.status != 0);
      CHECK(r.err.find("scene rejected before sending: " + it->where) != std::string::npos);
      CHECK(r.err.find(it->message) != std::string::npos);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK_FALSE(exists(out));
    }
  }
}

// The files this helper added to test/eastray/eastray_bad (which the
// firmware tests also send to the board as they are): each names its
// expected message in its header comment.
TEST_CASE("eastray probe: the added invalid scene files, through minrt and host-send", "[eastray][eprobe]") {
  const std::string dir = EASTRAY_BAD_DIR;
  const std::string out_dir = temp_dir();
  for (const char* n : {"sign-not-one", "ior-zero-glass", "range-kind-polygon", "number-too-long", "switch-not-0-or-1"}) {
    INFO(n);
    const std::string file = std::string(n) + ".ray";
    const std::string text = minrt::test::read_file(dir + "/" + file);
    const std::size_t e = text.find("expect: ");
    REQUIRE(e != std::string::npos);
    const std::string expect = file + ":" + text.substr(e + 8, text.find(" */", e) - e - 8);
    const std::string out = out_dir + "/" + n + ".png";
    const Run r = run(std::string(MINRT_BIN) + " -o " + out + " " + file, dir);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind(expect, 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(out));
    for (const char* protocol : {"raw", "course", "framed"}) {
      INFO(protocol);
      const Run s = run(std::string(MINRT_SEND_BIN) + " --sim --protocol " + protocol + " " + file + " -o " + out, dir);
      INFO(s.err);
      CHECK(s.status != 0);
      CHECK(s.err.find("scene rejected before sending: " + expect) != std::string::npos);
      CHECK_FALSE(exists(out));
    }
  }
}

TEST_CASE("eastray probe: macros that double at every level stop with an error", "[eastray][eprobe]") {
  // M0 -> M1 M1 -> ... : 2^30 copies of "1" if nothing stopped it.
  std::string text = kHead;
  for (int i = 0; i < 30; ++i) text += "#define M" + std::to_string(i) + " M" + std::to_string(i + 1) + " M" + std::to_string(i + 1) + "\n";
  text += "#define M30 1\nobj [ 2 grey 1  0 1 0  M0 ; ]\n";
  const std::string dir = temp_dir();
  write(dir + "/explode.ray", text);
  const Run r = run(std::string(MINRT_BIN) + " -o out.png explode.ray", dir);
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(r.err.rfind("explode.ray:38:", 0) == 0);
  CHECK(r.err.find("the scene expands past") != std::string::npos);
  CHECK_FALSE(exists(dir + "/out.png"));
}

TEST_CASE("eastray probe: an invalid scene writes nothing under its output statement's name either", "[eastray][eprobe]") {
  const std::string dir = temp_dir();
  for (const char* name : {"named.png", "named.tif", "named.fal"}) {
    INFO(name);
    write(dir + "/o.ray", std::string(kHead) + "output " + name + " ;\nobj [ 2 gold 1  0 1 0  1 ; ]\n");
    const Run r = run(std::string(MINRT_BIN) + " o.ray", dir);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("o.ray:8:9: error: undefined colour 'gold'", 0) == 0);
    CHECK_FALSE(exists(dir + "/" + name));
    CHECK_FALSE(exists(dir + "/named.png"));
    CHECK_FALSE(exists(dir + "/o.png"));
  }
  // From standard input: the message names <stdin>.
  write(dir + "/in.txt", "obj [ 2 gold 1  0 1 0  1 ; ]\n");
  const Run r = run("sh -c '" + std::string(MINRT_BIN) + " --scene-format eastray - -o s.png < in.txt'", dir);
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(r.err.rfind("<stdin>:1:9: error: undefined colour 'gold'", 0) == 0);
  CHECK_FALSE(exists(dir + "/s.png"));
}

// A quadric is the same surface at any scale, so a scene may write one with
// tiny coefficients; below float's least number (about 1.4e-45) all ten read
// as 0 and the object would silently vanish on the board's precision. It is
// an error naming the object, in every precision where it happens (written
// zeros too), and host-send, reading as the board does, refuses it.
TEST_CASE("eastray probe: a quadric whose coefficients all read as 0 is a located error", "[eastray][eprobe]") {
  const std::string dir = temp_dir();
  const std::string tiny = "0 grey 1  1e-50 1e-50 1e-50 0 0 0 0 -2e-50 0 -1e-50 ;";
  write(dir + "/tiny.ray", std::string(kHead) + "obj [ " + tiny + " ]\n");
  write(dir + "/tiny-range.ray", std::string(kHead) + "obj [ ( " + tiny.substr(0, 2) + tiny.substr(10) +
                                     " 2 grey 1  0 1 0  1 ; ) ]\n");
  write(dir + "/zeros.ray", std::string(kHead) + "obj [ 2 grey 1  0 1 0  1 ;\n  0 grey 1  0 0 0 0 0 0 0 0 0 0 ; ]\n");
  write(dir + "/tiny-double.ray", std::string(kHead) + "obj [ 0 grey 1  1e-400 1e-400 1e-400 0 0 0 0 0 0 -1e-400 ; ]\n");
  const std::string message = "the quadric's coefficients all read as 0";
  // Double keeps 1e-50: the scene renders there.
  Run r = run(std::string(MINRT_BIN) + " -o d.png tiny.ray", dir);
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(exists(dir + "/d.png"));
  struct Case {
    const char* file;
    const char* precision;
    const char* where;
  };
  for (const Case& c : {Case{"tiny.ray", "float", "tiny.ray:7:7:"}, Case{"tiny-range.ray", "float", "tiny-range.ray:7:9:"},
                        Case{"zeros.ray", "double", "zeros.ray:8:3:"}, Case{"zeros.ray", "float", "zeros.ray:8:3:"},
                        Case{"tiny-double.ray", "double", "tiny-double.ray:7:7:"}}) {
    INFO(c.file << " in " << c.precision);
    r = run(std::string(MINRT_BIN) + " --precision " + c.precision + " -o out.png " + c.file, dir);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind(std::string(c.where) + " error: " + message, 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(dir + "/out.png"));
  }
  r = run(std::string(MINRT_SEND_BIN) + " --sim tiny.ray -o board.png", dir);
  INFO(r.err);
  CHECK(r.status != 0);
  CHECK(r.err.find("scene rejected before sending: tiny.ray:7:7: error: " + message) != std::string::npos);
  CHECK_FALSE(exists(dir + "/board.png"));
}
