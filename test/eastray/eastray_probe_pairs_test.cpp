// EASTRAY equivalence pairs beyond ../shared: the same geometry written two ways must give the same image
// within float rounding (SPEC.md 1.6's deterministic metric: pixels whose
// largest channel difference exceeds 2, a few silhouette pixels allowed).
// Every quadric kind against the general quadric (kind 0) with the
// coefficients its definition gives (manual lines 1053-1195), under moves in
// every axis and order; finite kinds, capped cylinder and box against AND
// blocks; sign -1 against the complemented quadric; RANGE on and off in
// nested blocks; parts; lights at their limits; the no-shadow flag.
#include "eastray_probe_support.hpp"

using namespace eprobe;

namespace {

// 81x61: odd, so the centre pixel looks straight down the view line.
const char* kHead =
    "display 81 61 0 0 80 60 1 1 1 ;\n"
    "condition 4 0.01 0.00001 0 ;\n"
    "camera 1 3 10  0 0.8 0  0 10 0  22 0 ;\n"
    "sky 0.1 0.2 0.3 ;\nenv 0.25 0.25 0.25 ;\nshadow 1 ;\n"
    "e_light [ -1 2 1.5  0.8 0.8 0.8  0 1 ; ]\n"
    "color [\n"
    " floor 0.5 0.5 0.5  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
    " red 0.9 0.2 0.1  0 0 0  0 0 0  1 1  0  0 0.6 15 ;\n"
    " blue 0.1 0.3 0.9  0 0 0  0 0 0  1 1  0  0 0.6 15 ;\n"
    "]\n";

const Rgb kSky{25, 51, 76};

std::string with_floor(const std::string& objects, const std::string& extra = "") {
  return std::string(kHead) + extra + "obj [\n 1 floor 1  0 -1.5 0  0 1 0 ;\n" + objects + "\n]\n";
}
std::string bare(const std::string& objects, const std::string& extra = "") {
  return std::string(kHead) + extra + "obj [\n" + objects + "\n]\n";
}

// Same picture within rounding, in double and in the board's float, and a
// picture with something in it.
void same_image(const std::string& a, const std::string& b, int edge = 6, int least_covered = 150) {
  const EastrayImage ia = render(a), ib = render(b);
  dump_pair(a, b);
  const int n = differing(ia, ib);
  INFO("scene A:\n" << a << "\nscene B:\n" << b << "\ndiffering pixels: " << n);
  CHECK(n <= edge);
  CHECK(covered(ia, kSky) >= least_covered);
  // The board's arithmetic, float with the portable shims: the same bound.
  minrt::host::Variant f;
  f.precision = minrt::host::Precision::kFloat;
  f.shims = minrt::host::ShimSet::kPortable;
  const int nf = differing(render(a, "probe.ray", f), render(b, "probe.ray", f));
  INFO("differing pixels in float: " << nf);
  CHECK(nf <= edge);
}

}  // namespace

TEST_CASE("eastray probe: every quadric kind = the general quadric with its coefficients", "[eastray][eprobe]") {
  // Centre and a tilted, unnormalised axis, so every coefficient of kind 0
  // is non-zero (docs/eastray.md's kind table in world terms).
  const Vec3 c{0.3, 0.9, -0.2};
  const Vec3 ax{1, 2, 0.5};
  const std::string cs = vec(c) + "  " + vec(ax) + "  ";
  struct Kind {
    const char* name;
    std::string own;
    Quadric q;
  };
  const double s = 0.6, d = 0.35;  // slope r/t and waist / vertex distance
  const std::vector<Kind> kinds = {
      {"2 sphere", "2 red 1  " + vec(c) + "  0.9 ;", axial(c, ax, 1, 0, -0.81)},
      {"3 ellipsoid", "3 red 1  " + vec(c) + "  1.1 0.6 0.8 ;", ellipsoid(c, 1.1, 0.6, 0.8)},
      {"5 cylinder", "5 red 1  " + cs + "0.45 ;", axial(c, ax, 1, -1, -0.45 * 0.45)},
      {"4 cone", "4 red 1  " + cs + num(s) + " ;", axial(c, ax, 1, -(1 + s * s), 0)},
      // (x^2+y^2)/r^2 + z^2/q^2 - 1 with q 1.2 along the axis, r 0.5 across
      {"6 spheroid", "6 red 1  " + cs + "1.2 0.5 ;", axial(c, ax, 1 / 0.25, 1 / 1.44 - 1 / 0.25, -1)},
      {"7 one sheet", "7 red 1  " + cs + num(s) + " " + num(d) + " ;", axial(c, ax, 1, -(1 + s * s), -d * d)},
      {"8 two sheets", "8 red 1  " + cs + num(s) + " " + num(d) + " ;", axial(c, ax, 1, -(1 + s * s), s * s * d * d)},
  };
  for (const Kind& k : kinds) {
    SECTION(k.name) {
      same_image(with_floor(k.own), with_floor("0 red 1  " + k.q.kind0() + " ;"));
      // 13 numbers: a leading l m n taken as a translation (E1)
      Quadric at_origin = k.q.moved(move(":mx", -c[0]).then_inner(move(":my", -c[1])).then_inner(move(":mz", -c[2])));
      same_image(with_floor(k.own), with_floor("0 red 1  " + vec(c) + "  " + at_origin.kind0() + " ;"));
    }
  }
  SECTION("1 plane (inside opposite the normal)") {
    same_image(bare("1 red 1  0 0.5 0  1 2 0.5 ;"), bare("0 red 1  " + plane({0, 0.5, 0}, {1, 2, 0.5}).kind0() + " ;"),
               6, 1000);
  }
}

TEST_CASE("eastray probe: moves in every axis and order = the moved quadric = :mtx", "[eastray][eprobe]") {
  // An ellipsoid off the origin: the moves turn and stretch it about the
  // origin, nearest command first (line 1255).
  const Vec3 c{0.4, 0.2, 0.1};
  const std::string own = "3 red 1  " + vec(c) + "  0.9 0.5 0.35 ;";
  const Quadric local = ellipsoid(c, 0.9, 0.5, 0.35);
  const std::vector<Chain> chains = {
      {{{":rx", 35}, {":ry", 50}, {":rz", 20}}},
      {{{":rx", 35}, {":rz", 20}, {":ry", 50}}},
      {{{":ry", 50}, {":rx", 35}, {":rz", 20}}},
      {{{":ry", 50}, {":rz", 20}, {":rx", 35}}},
      {{{":rz", 20}, {":rx", 35}, {":ry", 50}}},
      {{{":rz", 20}, {":ry", 50}, {":rx", 35}}},
      {{{":mx", -0.3}, {":my", 1.1}, {":mz", 0.4}, {":ry", -70}}},
      {{{":rz", 30}, {":mx", 0.5}, {":sy", 1.6}, {":my", 0.8}}},
      {{{":my", 1}, {":sx", 1.3}, {":sz", 0.7}, {":rx", -40}, {":sy", 1.2}}},
      {{{":my", 1}, {":sx", -1}, {":rz", 25}}},  // a mirror
  };
  for (std::size_t i = 0; i < chains.size(); ++i) {
    const Chain& ch = chains[i];
    DYNAMIC_SECTION("chain " << ch.text()) {
      const std::string chained = with_floor("[ " + ch.text() + own + " ]");
      // as per-object moves (between kind and colour, E15)
      const std::string per_object = with_floor("3 " + ch.text() + "red 1  " + vec(c) + "  0.9 0.5 0.35 ;");
      const std::string quadric = with_floor("0 red 1  " + local.moved(ch.map()).kind0() + " ;");
      const std::string mtx = with_floor("[ " + ch.map().mtx() + " " + own + " ]");
      same_image(chained, quadric);
      same_image(chained, per_object, 0);
      same_image(chained, mtx);
    }
  }
  SECTION("moves split over nested blocks = one chain") {
    same_image(with_floor("[ :my 1 :rx 30 [ :rz 45 { :sx 1.5 " + own + " } ] ]"),
               with_floor("[ :my 1 :rx 30 :rz 45 :sx 1.5 " + own + " ]"), 0);
  }
  SECTION("a block's moves do not leak out of it (line 1260)") {
    same_image(with_floor("[ :mx 5 :ry 30 ] 2 blue 1  -0.8 0 0  0.5 ;" + own),
               with_floor("2 blue 1  -0.8 0 0  0.5 ;" + own), 0);
  }
  SECTION("non-uniform scale of a sphere = the ellipsoid") {
    same_image(with_floor(":sx 1.5 :sy 0.6 :sz 0.8  2 red 1  0.2 1 0  1 ;"),
               with_floor("3 red 1  0.3 0.6 0  1.5 0.6 0.8 ;"));
  }
  SECTION(":sx -1 mirrors: an off-centre box and cylinder land on the other side") {
    same_image(with_floor("[ :sx -1  16 red 1  0.8 0.3 0  0.4 0.6 0.3 ;  15 blue 1  -0.6 0.3 0.3  1 1 0  0.2 0.5 ; ]"),
               with_floor("16 red 1  -0.8 0.3 0  0.4 0.6 0.3 ;  15 blue 1  0.6 0.3 0.3  -1 1 0  0.2 0.5 ;"));
  }
  SECTION("the whole scene moved = the camera moved the other way") {
    // :ry 30 about the origin then :mx 1: the eye and the look-at points
    // go through the same map.
    const Chain ch{{{":mx", 1}, {":ry", 30}}};
    const Affine m = ch.map();
    const std::string objs = "1 floor 1  0 -1.5 0  0 1 0 ;  2 red 1  0 0.5 0  0.8 ;  16 blue 1  1.2 0 -0.5  0.4 0.4 0.4 ;";
    const std::string head_rest =
        "sky 0.1 0.2 0.3 ;\nenv 0.25 0.25 0.25 ;\nshadow 1 ;\n"
        "color [ floor 0.5 0.5 0.5  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
        " red 0.9 0.2 0.1  0 0 0  0 0 0  1 1  0  0 0.6 15 ;\n blue 0.1 0.3 0.9  0 0 0  0 0 0  1 1  0  0 0.6 15 ; ]\n";
    const std::string disp = "display 81 61 0 0 80 60 1 1 1 ;\ncondition 4 0.01 0.00001 0 ;\n";
    const std::string a = disp + "camera 1 3 10  0 0.8 0  0 10 0  22 0 ;\n" + head_rest +
                          "e_light [ -1 2 1.5  0.8 0.8 0.8  0 1 ; ]\nobj [ " + objs + " ]\n";
    const std::string b = disp + "camera " + vec(m.apply({1, 3, 10})) + "  " + vec(m.apply({0, 0.8, 0})) + "  " +
                          vec(m.apply({0, 10, 0})) + "  22 0 ;\n" + head_rest + "e_light [ " +
                          vec(m.apply_dir({-1, 2, 1.5})) + "  0.8 0.8 0.8  0 1 ; ]\nobj [ " + ch.text() + objs + " ]\n";
    same_image(a, b, 8, 1000);
  }
}

TEST_CASE("eastray probe: finite kinds = AND of the infinite kind and planes, under moves", "[eastray][eprobe]") {
  // Local axis +z through the origin; the whole object turned and moved,
  // so the caps and the slab are tilted in the world.
  const std::string moves = ":my 0.6 :rx -50 :ry 30 ";
  const std::string ax = "0 0 0  0 0 1  ";
  auto cut = [](double lo, double hi) {
    return "1 red 1  0 0 " + num(hi) + "  0 0 1 ;  1 red 1  0 0 " + num(lo) + "  0 0 -1 ;";
  };
  SECTION("10 = cone AND [0, h]") {
    same_image(with_floor("[ " + moves + "10 red 1  " + ax + "0.5 1 ; ]"),
               with_floor("[ " + moves + "{ 4 red 1  " + ax + "0.5 ; " + cut(0, 1) + " } ]"));
  }
  SECTION("11 = cone AND [-h, h]") {
    same_image(with_floor("[ " + moves + "11 red 1  " + ax + "0.5 1 ; ]"),
               with_floor("[ " + moves + "{ 4 red 1  " + ax + "0.5 ; " + cut(-1, 1) + " } ]"));
  }
  SECTION("12 = two sheets AND [0, h]") {
    same_image(with_floor("[ " + moves + "12 red 1  " + ax + "0.7 0.3 1.1 ; ]"),
               with_floor("[ " + moves + "{ 8 red 1  " + ax + "0.7 0.3 ; " + cut(0, 1.1) + " } ]"));
  }
  SECTION("13 = two sheets AND [-h, h]") {
    same_image(with_floor("[ " + moves + "13 red 1  " + ax + "0.7 0.3 1.1 ; ]"),
               with_floor("[ " + moves + "{ 8 red 1  " + ax + "0.7 0.3 ; " + cut(-1.1, 1.1) + " } ]"));
  }
  SECTION("14 = one sheet AND [-h, h]") {
    same_image(with_floor("[ " + moves + "14 red 1  " + ax + "0.4 0.3 0.9 ; ]"),
               with_floor("[ " + moves + "{ 7 red 1  " + ax + "0.4 0.3 ; " + cut(-0.9, 0.9) + " } ]"));
  }
  SECTION("15 = AND of kind 0 (the cylinder as coefficients) and two planes") {
    const Quadric cyl = axial({0, 0, 0}, {0, 0, 1}, 1, -1, -0.36);
    same_image(with_floor("[ " + moves + "15 red 1  " + ax + "0.6 0.8 ; ]"),
               with_floor("[ " + moves + "{ 0 red 1  " + cyl.kind0() + " ; " + cut(-0.8, 0.8) + " } ]"));
  }
  SECTION("16 = AND of six planes, moved") {
    same_image(with_floor("[ " + moves + "16 red 1  0.1 0.2 0  0.7 0.4 0.5 ; ]"),
               with_floor("[ " + moves + "{ 1 red 1  0.8 0 0  1 0 0 ;  1 red 1  -0.6 0 0  -1 0 0 ;"
                          "  1 red 1  0 0.6 0  0 1 0 ;  1 red 1  0 -0.2 0  0 -1 0 ;"
                          "  1 red 1  0 0 0.5  0 0 1 ;  1 red 1  0 0 -0.5  0 0 -1 ; } ]"));
  }
  SECTION("16's face colours = the AND's planes in those colours (1 +x ... 6 -z, line 1194)") {
    same_image(with_floor("[ :ry 35 :rx 20  16 floor 1  0 0.4 0  0.6 0.6 0.6  1 red  2 blue  3 red  4 blue  5 blue  6 red ; ]"),
               with_floor("[ :ry 35 :rx 20 { 1 red 1  0.6 0 0  1 0 0 ;  1 blue 1  -0.6 0 0  -1 0 0 ;"
                          "  1 red 1  0 1 0  0 1 0 ;  1 blue 1  0 -0.2 0  0 -1 0 ;"
                          "  1 blue 1  0 0 0.6  0 0 1 ;  1 red 1  0 0 -0.6  0 0 -1 ; } ]"));
  }
}

TEST_CASE("eastray probe: CSG written two ways", "[eastray][eprobe]") {
  const std::string box = "16 red 1  0 0.3 0  0.8 0.8 0.8 ;";
  const Quadric ball = axial({0.5, 0.9, 0.5}, {0, 1, 0}, 1, 0, -0.49);
  SECTION("difference: sign -1 = the complemented quadric with sign 1") {
    same_image(with_floor("{ " + box + " 2 blue -1  0.5 0.9 0.5  0.7 ; }"),
               with_floor("{ " + box + " 0 blue 1  " + ball.negated().kind0() + " ; }"));
    same_image(with_floor("{ " + box + " 0 blue -1  " + ball.kind0() + " ; }"),
               with_floor("{ " + box + " 0 blue 1  " + ball.negated().kind0() + " ; }"));
  }
  SECTION("plane with sign -1 = the plane with the opposite normal") {
    same_image(with_floor("{ 2 red 1  0 0.3 0  1 ;  1 blue -1  0 0.5 0  1 1 0 ; }"),
               with_floor("{ 2 red 1  0 0.3 0  1 ;  1 blue 1  0 0.5 0  -1 -1 0 ; }"));
  }
  SECTION("OR of ORs = one OR; AND is associative") {
    same_image(with_floor("[ [ 2 red 1  -0.6 0.3 0  0.6 ; ] [ 2 blue 1  0.6 0.3 0  0.6 ; ] ]"),
               with_floor("2 red 1  -0.6 0.3 0  0.6 ;  2 blue 1  0.6 0.3 0  0.6 ;"));
    same_image(with_floor("{ { 2 red 1  -0.3 0.3 0  0.8 ; 2 blue 1  0.3 0.3 0  0.8 ; } 5 red 1  0 0 0  0 1 0  0.6 ; }"),
               with_floor("{ 2 red 1  -0.3 0.3 0  0.8 ; { 2 blue 1  0.3 0.3 0  0.8 ; 5 red 1  0 0 0  0 1 0  0.6 ; } }"));
  }
  SECTION("box minus two solids: flat AND = nested ANDs of the complements") {
    same_image(with_floor("{ " + box + " 2 blue -1  0.8 0.8 0.8  0.5 ;  5 blue -1  0 0 0  1 0 0  0.3 ; }"),
               with_floor("{ " + box + " { 2 blue -1  0.8 0.8 0.8  0.5 ; } { 5 blue -1  0 0 0  1 0 0  0.3 ; } }"),
               0);
  }
  SECTION("capped cylinder under moves = AND of the infinite cylinder and two planes, face colours") {
    same_image(
        with_floor("[ :mx -0.2 :rz 40  15 red 1  0 0.3 0  0 1 0  0.5 0.9  t blue  b blue ; ]"),
        with_floor("[ :mx -0.2 :rz 40 { 5 red 1  0 0.3 0  0 1 0  0.5 ;  1 blue 1  0 1.2 0  0 1 0 ;  1 blue 1  0 -0.6 0  0 -1 0 ; } ]"));
  }
}

TEST_CASE("eastray probe: RANGE on = off in nested blocks, whatever its kind", "[eastray][eprobe]") {
  const std::string inner = "2 red 1  -0.5 0.3 0  0.4 ;  16 blue 1  0.5 0.3 0  0.3 0.3 0.3 ;";
  const std::string plain = with_floor(inner);
  const std::string ball = axial({0, 0.3, 0}, {0, 1, 0}, 1, 0, -1.44).kind0();
  const std::vector<std::string> heads = {
      "2  0 0.3 0  1.2",
      "0  " + ball,
      "3  0 0.3 0  1.2 0.6 0.6",
      "5  0 0.3 0  1 0 0  0.7",
      "6  0 0.3 0  1 0 0  1.3 0.7",
      "7  0 0.3 0  1 0 0  0.2 0.7",
      "1  0 5 0  0 1 0",
      "4  -3 0.3 0  1 0 0  0.5",
      "8  -3 0.3 0  1 0 0  0.5 0.1",
  };
  for (const std::string& h : heads) {
    DYNAMIC_SECTION("RANGE head " << h) {
      same_image(plain, with_floor("( " + h + " ; " + inner + " )"), 0);
      // nested: RANGE inside RANGE, inside an AND with a big ball, inside an OR
      same_image(with_floor("{ 2 red 1  0 0.3 0  2 ; [ " + inner + " ] }"),
                 with_floor("{ 2 red 1  0 0.3 0  2 ; [ ( " + h + " ; ( 2  -0.5 0.3 0  0.45 ; 2 red 1  -0.5 0.3 0  0.4 ; )"
                            " 16 blue 1  0.5 0.3 0  0.3 0.3 0.3 ; ) ] }"),
                 0);
    }
  }
  SECTION("RANGE under moves, and its moves stay inside") {
    same_image(with_floor("[ :ry 40 :mx 0.3 " + inner + " ] 2 red 1  0 -1 1.5  0.3 ;"),
               with_floor("[ :ry 40 ( 2  0.3 0.3 0  1.4 ; :mx 0.3 " + inner + " ) :mx 0.3 ] 2 red 1  0 -1 1.5  0.3 ;"), 0);
  }
  SECTION("an empty RANGE, AND or OR is no item: removing it changes nothing") {
    const std::string diff = "{ 16 red 1  0 0.3 0  0.7 0.7 0.7 ;  2 blue -1  0.4 0.7 0.4  0.6 ; ";
    for (const char* empty : {"( 2  0 0.3 0  1.5 ; )", "( 2  5 5 5  0.1 ; )", "{ }", "[ ]", "{ [ ] ( 2 0 0 0 9 ; ) }",
                              "[ :mx 1 -2  0 3 3  1 1 1  0 ; ]"}) {
      INFO(empty);
      const std::string light = std::string(empty).find("-2") != std::string::npos
                                    ? "p_light [ 1 3 3  1 1 1  0 ; ]\n" : "";
      same_image(with_floor(diff + "}", light), with_floor(diff + empty + " }"), 0);
      same_image(with_floor("[ " + diff + "} ]", light), with_floor("[ " + diff + "} " + empty + " ]"), 0);
    }
  }
  SECTION("shadow rays through a RANGE they start outside of") {
    same_image(with_floor("2 red 1  0 1.2 0  0.5 ;"), with_floor("( 2  0 1.2 0  0.6 ; 2 red 1  0 1.2 0  0.5 ; )"), 0);
  }
}

TEST_CASE("eastray probe: parts, a part calling a part, with moves = inline", "[eastray][eprobe]") {
  const std::string leg = "15 blue 1  0 0 0  0 1 0  0.08 0.5 ;";
  const std::string top = "16 red 1  0 0.55 0  0.6 0.05 0.4 ;";
  const std::string table_inline =
      "[ " + top + " [ :mx 0.5 :mz 0.3 " + leg + " ] [ :mx -0.5 :mz 0.3 " + leg + " ] [ :mx 0.5 :mz -0.3 " + leg +
      " ] [ :mx -0.5 :mz -0.3 " + leg + " ] ]";
  const std::string a = with_floor("[ :my -1 :ry 25 " + table_inline + " ] [ :mx 1.3 :my -0.4 :rz 90 " + table_inline + " ]");
  const std::string parts =
      "obj table [ " + top + " [ :mx 0.5 :mz 0.3 leg ; ] [ :mx -0.5 :mz 0.3 leg ; ] [ :mx 0.5 :mz -0.3 leg ; ]"
      " [ :mx -0.5 :mz -0.3 leg ; ] ]\nobj leg [ " + leg + " ]\nobj unused [ 2 red 1  0 0 0  5 ; ]\n";
  const std::string b = with_floor("[ :my -1 :ry 25 table ; ] [ :mx 1.3 :my -0.4 :rz 90 table ; ]") + parts;
  same_image(a, b, 0);
  SECTION("a part's own moves stay inside it") {
    same_image(with_floor("p ; 2 red 1  0 0.2 0  0.5 ;") + "obj p [ :mx 1 :sy 2 2 blue 1  0 0 0  0.3 ; ]\n",
               with_floor("[ :mx 1 :sy 2 2 blue 1  0 0 0  0.3 ; ] 2 red 1  0 0.2 0  0.5 ;"), 0);
  }
  SECTION("a part called inside AND joins the AND") {
    same_image(with_floor("{ 16 red 1  0 0.3 0  0.7 0.7 0.7 ; hole ; }") + "obj hole [ 2 blue -1  0.4 0.7 0.4  0.6 ; ]\n",
               with_floor("{ 16 red 1  0 0.3 0  0.7 0.7 0.7 ; 2 blue -1  0.4 0.7 0.4  0.6 ; }"), 0);
  }
}

TEST_CASE("eastray probe: polygon meshes written two ways", "[eastray][eprobe]") {
  // A square pyramid (apex up) and its four triangles plus the base.
  const std::string verts = "p 1 -0.7 -0.2 -0.7  p 2 0.7 -0.2 -0.7  p 3 0.7 -0.2 0.7  p 4 -0.7 -0.2 0.7  p 9 0 1.2 0 ";
  const std::string faces = "P 4 3 9 ;  P 3 2 9 ;  P 2 1 9 ;  P 1 4 9 ;  P 1 2 3 4 ; ";
  const std::string mesh = "20 red 1 < " + verts + faces + "> ;";
  SECTION("faces started at another vertex, same winding") {
    same_image(with_floor(mesh), with_floor("20 red 1 < " + verts + "P 3 9 4 ;  P 9 3 2 ;  P 1 9 2 ;  P 4 9 1 ;  P 3 4 1 2 ; > ;"), 0);
  }
  SECTION("the quad base as two triangles; vertices numbered otherwise") {
    same_image(with_floor(mesh),
               with_floor("20 red 1 < p 100 -0.7 -0.2 -0.7  p 0 0.7 -0.2 -0.7  p 7 0.7 -0.2 0.7  p 55 -0.7 -0.2 0.7  p 3 0 1.2 0 "
                          "P 55 7 3 ;  P 7 0 3 ;  P 0 100 3 ;  P 100 55 3 ;  P 100 0 7 ;  P 100 7 55 ; > ;"),
               2);
  }
  SECTION("shared vertices = every face with its own copies") {
    same_image(with_floor(mesh),
               with_floor("20 red 1 < p 0 -0.7 -0.2 0.7  p 1 0.7 -0.2 0.7  p 2 0 1.2 0  p 3 0.7 -0.2 0.7  p 4 0.7 -0.2 -0.7"
                          "  p 5 0 1.2 0  p 6 0.7 -0.2 -0.7  p 7 -0.7 -0.2 -0.7  p 8 0 1.2 0  p 10 -0.7 -0.2 -0.7"
                          "  p 11 -0.7 -0.2 0.7  p 12 0 1.2 0  p 13 -0.7 -0.2 -0.7  p 14 0.7 -0.2 -0.7"
                          "  p 15 0.7 -0.2 0.7  p 16 -0.7 -0.2 0.7"
                          "  P 0 1 2 ;  P 3 4 5 ;  P 6 7 8 ;  P 10 11 12 ;  P 13 14 15 16 ; > ;"),
               0);
  }
  SECTION("one mesh = two meshes; a face colour = a mesh of that colour") {
    same_image(with_floor("20 red 1 < " + verts + "P 4 3 9 ; c blue  P 3 2 9 ;  P 2 1 9 ;  P 1 4 9 ;  P 1 2 3 4 ; > ;"),
               with_floor("20 blue 1 < " + verts + "P 4 3 9 ; > ;  20 red 1 < " + verts +
                          "P 3 2 9 ;  P 2 1 9 ;  P 1 4 9 ;  P 1 2 3 4 ; > ;"),
               0);
  }
  SECTION("a mesh under moves = the moved vertices") {
    const Chain ch{{{":mx", 0.3}, {":ry", 35}, {":sy", 0.8}}};
    const Affine m = ch.map();
    auto p = [&](int id, Vec3 v) { return "p " + std::to_string(id) + " " + vec(m.apply(v)) + " "; };
    same_image(with_floor("20 " + ch.text() + "red 1 < " + verts + faces + "> ;"),
               with_floor("20 red 1 < " + p(1, {-0.7, -0.2, -0.7}) + p(2, {0.7, -0.2, -0.7}) + p(3, {0.7, -0.2, 0.7}) +
                          p(4, {-0.7, -0.2, 0.7}) + p(9, {0, 1.2, 0}) + faces + "> ;"),
               2);
  }
}

TEST_CASE("eastray probe: lights at their limits, object lights and the n flag", "[eastray][eprobe]") {
  const std::string objs = "2 red 1  0 0.3 0  0.7 ;  16 blue 1  1.2 -0.9 0.6  0.3 0.6 0.3 ;";
  auto scene = [&](const std::string& lights, const std::string& objects) {
    return std::string("display 81 61 0 0 80 60 1 1 1 ;\ncondition 4 0.01 0.00001 0 ;\n"
                       "camera 1 3 10  0 0.3 0  0 10 0  22 0 ;\nsky 0.1 0.2 0.3 ;\nenv 0.1 0.1 0.1 ;\n") +
           lights +
           "color [ floor 0.5 0.5 0.5  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
           " red 0.9 0.2 0.1  0 0 0  0 0 0  1 1  0  0 0.6 15 ;\n blue 0.1 0.3 0.9  0 0 0  0 0 0  1 1  0  0 0.6 15 ; ]\n"
           "obj [ 1 floor 1  0 -1.5 0  0 1 0 ; " + objects + " ]\n";
  };
  SECTION("s_light with spread 0 = p_light when everything is in front of it") {
    // spread 0: cos^0 = 1 over the half space the spot faces (docs: 0 beyond 90 degrees).
    same_image(scene("p_light [ -1 4 2  1 1 0.9  6 ; ]\n", objs),
               scene("s_light [ -1 4 2  -1 -10 2  1 1 0.9  0 6 ; ]\n", objs), 0);
  }
  SECTION("p_light far away with no fall-off = e_light in its direction (shadows within the edges)") {
    same_image(scene("p_light [ -20000 40000 30000  1 1 1  0 ; ]\n", objs),
               scene("e_light [ -2 4 3  1 1 1  0 1 ; ]\n", objs), 8);
  }
  SECTION("two lights in one block = two blocks") {
    same_image(scene("p_light [ -1 4 2  0.5 0.5 0.5  6 ;  2 3 3  0.3 0.6 0.3  0 ; ]\n", objs),
               scene("p_light [ -1 4 2  0.5 0.5 0.5  6 ; ]\np_light [ 2 3 3  0.3 0.6 0.3  0 ; ]\n", objs), 0);
  }
  SECTION("object lights -1, -2, -3 under moves = the statements at the moved places") {
    const Chain ch{{{":my", 1}, {":rz", 30}, {":mx", 0.5}}};
    const Affine m = ch.map();
    same_image(scene("", "[ " + ch.text() + " -1  0 1 1  0.6 0.6 0.6  0 1 ;  -2  -1 2 1  0.5 0.4 0.3  5 ;"
                         "  -3  1 2 2  0 -1 0  0.3 0.5 0.3  3 8 ; ] " + objs),
               scene("e_light [ " + vec(m.apply_dir({0, 1, 1})) + "  0.6 0.6 0.6  0 1 ; ]\np_light [ " +
                         vec(m.apply({-1, 2, 1})) + "  0.5 0.4 0.3  5 ; ]\ns_light [ " + vec(m.apply({1, 2, 2})) + "  " +
                         vec(m.apply({0, -1, 0})) + "  0.3 0.5 0.3  3 8 ; ]\n",
                     objs),
               2);
  }
  SECTION("an e_light with n casts no shadow = shadow 0 for that light") {
    same_image(scene("e_light [ -1 2 1  1 1 1  0 1 n ; ]\n", objs), scene("shadow 0 ;\ne_light [ -1 2 1  1 1 1  0 1 ; ]\n", objs), 0);
  }
  SECTION("p_light r dist shorter than every point = shadow 0; r -1 = shadows") {
    same_image(scene("p_light [ -1 4 2  1 1 1  6 r 0.01 ; ]\n", objs), scene("shadow 0 ;\np_light [ -1 4 2  1 1 1  6 ; ]\n", objs), 0);
    same_image(scene("p_light [ -1 4 2  1 1 1  6 r -1 ; ]\n", objs), scene("p_light [ -1 4 2  1 1 1  6 ; ]\n", objs), 0);
  }
  SECTION("r dist is measured to the shaded point (C3): nearer points get shadows, farther ones none") {
    // Light 4 above the ball's centre: the ball's top is 3 from it, the
    // box at least 4.3, the floor at least 5.5.
    const std::string far_off = "shadow 0 ;\np_light [ 0 4.3 0  1 1 1  0 ; ]\n";
    same_image(scene("p_light [ 0 4.3 0  1 1 1  0 r 4 ; ]\n", objs), scene(far_off, objs), 0);
    same_image(scene("s_light [ 0 4.3 0  0 0 0  1 1 1  1 0 r 4 ; ]\n", objs),
               scene("shadow 0 ;\ns_light [ 0 4.3 0  0 0 0  1 1 1  1 0 ; ]\n", objs), 0);
    const EastrayImage near = render(scene("p_light [ 0 4.3 0  1 1 1  0 r 6 ; ]\n", objs));
    CHECK(differing(near, render(scene(far_off, objs))) > 20);  // the floor's shadows
  }
  SECTION("objects that all carry n = shadow 0") {
    same_image(scene("e_light [ -1 2 1  1 1 1  0 1 ; ]\n", "2 red 1  0 0.3 0  0.7 n ;  16 blue 1  1.2 -0.9 0.6  0.3 0.6 0.3 n ;"),
               scene("shadow 0 ;\ne_light [ -1 2 1  1 1 1  0 1 ; ]\n", objs), 0);
  }
  SECTION("polygon faces with n = shadow 0") {
    const std::string tri = "< p 0 -0.5 0 0  p 1 0.5 0 0  p 2 0 1 0  P 0 1 2 ; ";
    same_image(scene("e_light [ -1 2 1  1 1 1  0 1 ; ]\n", "20 red 1 " + tri + "n > ;"),
               scene("shadow 0 ;\ne_light [ -1 2 1  1 1 1  0 1 ; ]\n", "20 red 1 " + tri + "> ;"), 0);
  }
  SECTION("voxel 0 = voxel 16 (line 240: only speed)") {
    same_image(scene("voxel 0 ;\ne_light [ -1 2 1  1 1 1  0 1 ; ]\n", objs),
               scene("voxel 16 ;\ne_light [ -1 2 1  1 1 1  0 1 ; ]\n", objs), 0);
  }
}

TEST_CASE("eastray probe: the preprocessor and the text's forms", "[eastray][eprobe]") {
  const std::string objs = "2 red 1  -0.5 0.4 0  0.5 ;  16 blue 1  0.7 0 0.2  0.3 0.6 0.3 ;";
  const std::string plain = with_floor(objs);
  const EastrayImage reference = render(plain);
  SECTION("CR LF line ends, tabs and a DOS end-of-file mark") {
    std::string dos;
    for (char ch : plain) {
      if (ch == '\n') dos += "\r\n";
      else if (ch == ' ') dos += '\t';
      else dos += ch;
    }
    dos += "\x1a";
    CHECK(render(dos).rgb == reference.rgb);
    CHECK(render(plain + "\x1a this is not read [ { (").rgb == reference.rgb);
  }
  SECTION("comments touching tokens, spanning lines, between a kind and its colour") {
    CHECK(render(with_floor("2/* a */red/*\n*/1  -0.5 0.4 0/**/0.5 ;  16 blue 1  0.7 0 0.2  0.3 0.6 0.3 ;")).rgb ==
          reference.rgb);
  }
  SECTION("one number spelt several ways") {
    const char* spellings[][2] = {{"-.5", ".5"},     {"-0.5", "+0.5"},       {"-5e-1", "5e-1"},
                                  {"-5.E-1", "5.E-1"}, {"-0.50000", "0.50000"}, {"-50e-2", "50e-2"}};
    for (const auto& sp : spellings) {
      INFO(sp[0] << " " << sp[1]);
      CHECK(render(with_floor(std::string("2 red 1  ") + sp[0] + " 0.4 0  " + sp[1] +
                              " ;  16 blue 1  0.7 0 0.2  0.3 0.6 0.3 ;")).rgb == reference.rgb);
    }
  }
  SECTION("#define in numbers, negated, in other defines, several tokens, redefined") {
    const std::string text = std::string("#define H 0.5\n#define AT -H 0.4 0\n#define BALL 2 red 1\n") +
                             "#define HALF 0.3\n" + kHead + "obj [\n 1 floor 1  0 -1.5 0  0 1 0 ;\n" +
                             "BALL  AT  H ;\n#define HALF 0.6\n16 blue 1  0.7 0 0.2  0.3 HALF 0.3 ;\n]\n";
    CHECK(render(text).rgb == reference.rgb);
  }
  SECTION("#include \"...\" beside the including file, nested, and <...> from EASTRAY with a DOS path") {
    const std::string dir = temp_dir();
    mkdir((dir + "/parts").c_str(), 0755);
    mkdir((dir + "/lib").c_str(), 0755);
    mkdir((dir + "/lib/sub").c_str(), 0755);
    write(dir + "/parts/ball.h", "#include \"radius.h\"\n2 red 1  -0.5 0.4 0  R ;\n#include <sub\\box.h>\n");
    write(dir + "/parts/radius.h", "/* beside ball.h, not beside the scene */\n#define R 0.5\n");
    write(dir + "/lib/sub/box.h", "16 blue 1  0.7 0 0.2  0.3 0.6 0.3 ;\n");
    write(dir + "/scene.ray", with_floor("#include \"parts/ball.h\"\n"));
    setenv("EASTRAY", (dir + "/lib/").c_str(), 1);
    const EastrayImage inc = render(minrt::test::read_file(dir + "/scene.ray"), dir + "/scene.ray");
    unsetenv("EASTRAY");
    CHECK(inc.rgb == reference.rgb);
  }
  SECTION("a polygon inside AND and RANGE blocks is an independent surface (line 1222)") {
    const std::string tri = "20 blue 1 < p 0 -1 -1 1  p 1 1 -1 1  p 2 0 1.2 1  P 0 1 2 ; > ;";
    same_image(with_floor("2 red 1  0 0.3 0  0.8 ; " + tri), with_floor("{ 2 red 1  0 0.3 0  0.8 ; " + tri + " }"), 0);
    same_image(with_floor("2 red 1  0 0.3 0  0.8 ; " + tri),
               with_floor("( 2  0 0.3 0  0.9 ; 2 red 1  0 0.3 0  0.8 ; ) " + tri), 0);
  }
  SECTION("smooth shading over coplanar faces = flat") {
    const std::string v = "p 0 -1 -0.5 0  p 1 0 -0.5 0.3  p 2 1 -0.5 0  p 3 1 1 0  p 4 0 1 0.3  p 5 -1 1 0 ";
    // two flat panels meeting at a crease: smooth only within each panel
    same_image(with_floor("20 red 1 < " + v + "P 0 1 4 ; s  P 0 4 5 ; s k 2  P 1 2 3 ;  P 1 3 4 ; > ;"),
               with_floor("20 red 1 < " + v + "P 0 1 4 ;  P 0 4 5 ;  P 1 2 3 ;  P 1 3 4 ; > ;"), 0);
  }
}

TEST_CASE("eastray probe: glass written two ways refracts the same (rays inside CSG)", "[eastray][eprobe]") {
  // Transparent bodies: the rays that enter must find the same exits, so the
  // inside/outside logic of CSG and of the finite kinds is exercised too.
  const std::string glass =
      "color [ glass 0.05 0.05 0.05  1 1 1  0.9 0.95 1  1.5 3  0  0 0.5 30 ; ]\ncondition 6 0 0.00001 1 ;\n";
  const std::string behind = "16 red 1  -1 0.3 -2.5  0.4 1.2 0.3 ;  2 blue 1  1 0 -2  0.6 ;";
  auto s = [&](const std::string& objs) { return with_floor(behind + " " + objs, glass); };
  SECTION("sphere = kind 0") {
    same_image(s("2 glass 1  0 0.4 0.5  0.9 ;"), s("0 glass 1  " + axial({0, 0.4, 0.5}, {0, 1, 0}, 1, 0, -0.81).kind0() + " ;"), 10);
  }
  SECTION("capped cylinder = AND, tilted") {
    same_image(s("[ :rz 30 :rx 20 15 glass 1  0 0.3 0.5  0 1 0  0.6 0.7 ; ]"),
               s("[ :rz 30 :rx 20 { 5 glass 1  0 0.3 0.5  0 1 0  0.6 ;  1 glass 1  0 1 0.5  0 1 0 ;  1 glass 1  0 -0.4 0.5  0 -1 0 ; } ]"),
               10);
  }
  SECTION("box = AND of six planes, turned") {
    same_image(s("[ :ry 30 16 glass 1  0 0.3 0.5  0.7 0.7 0.5 ; ]"),
               s("[ :ry 30 { 1 glass 1  0.7 0 0  1 0 0 ;  1 glass 1  -0.7 0 0  -1 0 0 ;  1 glass 1  0 1 0  0 1 0 ;"
                 "  1 glass 1  0 -0.4 0  0 -1 0 ;  1 glass 1  0 0 1  0 0 1 ;  1 glass 1  0 0 0  0 0 -1 ; } ]"),
               10);
  }
  SECTION("a glass block with a spherical hollow: sign -1 = the negated quadric") {
    same_image(s("{ 16 glass 1  0 0.3 0.5  0.8 0.8 0.5 ;  2 glass -1  0.2 0.5 0.6  0.5 ; }"),
               s("{ 16 glass 1  0 0.3 0.5  0.8 0.8 0.5 ;  0 glass 1  " +
                 axial({0.2, 0.5, 0.6}, {0, 1, 0}, 1, 0, -0.25).negated().kind0() + " ; }"),
               10);
  }
}

TEST_CASE("eastray probe: the same scene organised otherwise", "[eastray][eprobe]") {
  const std::string a = "2 red 1  -0.5 0.4 0  0.5 ;", b = "16 blue 1  0.7 0 0.2  0.3 0.6 0.3 ;";
  const std::string one = with_floor(a + " " + b);
  SECTION("two unnamed objs are both drawn (E19) = one obj with both") {
    same_image(one, with_floor(a) + "obj [ " + b + " ]\n", 0);
  }
  SECTION("a part defined before the main obj = after it") {
    same_image(std::string(kHead) + "obj p [ " + b + " ]\nobj [\n 1 floor 1  0 -1.5 0  0 1 0 ;\n" + a + " p ;\n]\n",
               with_floor(a + " p ;") + "obj p [ " + b + " ]\n", 0);
  }
  SECTION("colours by number = by name; statements in another order") {
    same_image(one, with_floor("2 1 1  -0.5 0.4 0  0.5 ;  16 2 1  0.7 0 0.2  0.3 0.6 0.3 ;"), 0);
    same_image(one, "color [ floor 0.5 0.5 0.5  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
                    " red 0.9 0.2 0.1  0 0 0  0 0 0  1 1  0  0 0.6 15 ;\n blue 0.1 0.3 0.9  0 0 0  0 0 0  1 1  0  0 0.6 15 ; ]\n"
                    "obj [\n 1 floor 1  0 -1.5 0  0 1 0 ;\n" + a + " " + b + "\n]\n"
                    "e_light [ -1 2 1.5  0.8 0.8 0.8  0 1 ; ]\nshadow 1 ;\nenv 0.25 0.25 0.25 ;\nsky 0.1 0.2 0.3 ;\n"
                    "camera 1 3 10  0 0.8 0  0 10 0  22 0 ;\ncondition 4 0.01 0.00001 0 ;\ndisplay 81 61 0 0 80 60 1 1 1 ;\n",
               0);
  }
  SECTION("a display window = the full image inside it, black outside") {
    std::string win = one;
    win.replace(win.find("display 81 61 0 0 80 60"), 23, "display 81 61 7 5 60 44");
    const EastrayImage full = render(one), part = render(win);
    int checked = 0;
    for (int y = 0; y < 61; ++y)
      for (int x = 0; x < 81; ++x) {
        const Rgb f = px(full, x, y), p = px(part, x, y);
        const bool inside = x >= 7 && x <= 60 && y >= 5 && y <= 44;
        INFO("pixel " << x << " " << y);
        if (inside) REQUIRE((f.r == p.r && f.g == p.g && f.b == p.b));
        else REQUIRE(p.r + p.g + p.b == 0);
        ++checked;
      }
    CHECK(checked == 81 * 61);
  }
}

TEST_CASE("eastray probe: finite kinds under non-uniform moves = AND of moved kind-0 solids", "[eastray][eprobe]") {
  // The object keeps its local frame (axis +z); the chain stretches and
  // shears it. The other side writes every solid already moved, as kind 0
  // coefficients, with no moves: caps, slabs and normals must agree.
  const Chain ch{{{":my", 0.5}, {":rx", -60}, {":sx", 1.4}, {":ry", 35}, {":sz", 0.6}, {":rz", 20}}};
  const Affine m = ch.map();
  auto and_of = [&](const std::vector<Quadric>& parts) {
    std::string s = "{ ";
    for (const Quadric& q : parts) s += "0 red 1  " + q.moved(m).kind0() + " ;  ";
    return s + "}";
  };
  const Quadric top = plane({0, 0, 0.8}, {0, 0, 1}), bottom = plane({0, 0, -0.8}, {0, 0, -1}),
                base = plane({0, 0, 0}, {0, 0, -1});
  const double s = 0.6, d = 0.3;
  SECTION("15 cylinder") {
    same_image(with_floor("[ " + ch.text() + " 15 red 1  0 0 0  0 0 1  0.5 0.8 ; ]"),
               with_floor(and_of({axial({0, 0, 0}, {0, 0, 1}, 1, -1, -0.25), top, bottom})));
  }
  SECTION("11 cone, both nappes") {
    same_image(with_floor("[ " + ch.text() + " 11 red 1  0 0 0  0 0 1  " + num(s) + " 0.8 ; ]"),
               with_floor(and_of({axial({0, 0, 0}, {0, 0, 1}, 1, -(1 + s * s), 0), top, bottom})));
  }
  SECTION("10 cone, one nappe") {
    same_image(with_floor("[ " + ch.text() + " 10 red 1  0 0 0  0 0 1  " + num(s) + " 0.8 ; ]"),
               with_floor(and_of({axial({0, 0, 0}, {0, 0, 1}, 1, -(1 + s * s), 0), top, base})));
  }
  SECTION("14 one sheet") {
    same_image(with_floor("[ " + ch.text() + " 14 red 1  0 0 0  0 0 1  " + num(s) + " " + num(d) + " 0.8 ; ]"),
               with_floor(and_of({axial({0, 0, 0}, {0, 0, 1}, 1, -(1 + s * s), -d * d), top, bottom})));
  }
  SECTION("13 and 12 two sheets") {
    same_image(with_floor("[ " + ch.text() + " 13 red 1  0 0 0  0 0 1  " + num(s) + " " + num(d) + " 0.8 ; ]"),
               with_floor(and_of({axial({0, 0, 0}, {0, 0, 1}, 1, -(1 + s * s), s * s * d * d), top, bottom})));
    same_image(with_floor("[ " + ch.text() + " 12 red 1  0 0 0  0 0 1  " + num(s) + " " + num(d) + " 0.8 ; ]"),
               with_floor(and_of({axial({0, 0, 0}, {0, 0, 1}, 1, -(1 + s * s), s * s * d * d), top, base})));
  }
  SECTION("16 box") {
    same_image(with_floor("[ " + ch.text() + " 16 red 1  0 0 0  0.5 0.4 0.3 ; ]"),
               with_floor(and_of({plane({0.5, 0, 0}, {1, 0, 0}), plane({-0.5, 0, 0}, {-1, 0, 0}), plane({0, 0.4, 0}, {0, 1, 0}),
                                  plane({0, -0.4, 0}, {0, -1, 0}), plane({0, 0, 0.3}, {0, 0, 1}),
                                  plane({0, 0, -0.3}, {0, 0, -1})})));
  }
}

TEST_CASE("eastray probe: the board draws pair scenes as the host's float model does", "[eastray][eprobe]") {
  // A sample of the scenes above, sent with host-send to the simulated
  // board: its PNG is the bytes minrt writes in float with the portable shims.
  const Chain ch{{{":my", 0.5}, {":rx", -60}, {":sx", 1.4}, {":ry", 35}, {":sz", 0.6}, {":rz", 20}}};
  const std::string glass = "color [ glass 0.05 0.05 0.05  1 1 1  0.9 0.95 1  1.5 3  0  0 0.5 30 ; ]\ncondition 6 0 0.00001 1 ;\n";
  const std::vector<std::string> scenes = {
      with_floor("0 red 1  " + axial({0.3, 0.9, -0.2}, {1, 2, 0.5}, 1, -1.36, 0.36 * 0.1225).kind0() + " ;"),
      with_floor("[ " + ch.map().mtx() + " 3 red 1  0.4 0.2 0.1  0.9 0.5 0.35 ; ]"),
      with_floor("[ " + ch.text() + " 13 red 1  0 0 0  0 0 1  0.6 0.3 0.8 ; ]"),
      with_floor("{ 2 red 1  0 0.3 0  2 ; [ ( 7  0 0.3 0  1 0 0  0.2 0.7 ; ( 2  -0.5 0.3 0  0.45 ; 2 red 1  -0.5 0.3 0  0.4 ; )"
                 " 16 blue 1  0.5 0.3 0  0.3 0.3 0.3 ; ) ] }"),
      with_floor("{ 16 glass 1  0 0.3 0.5  0.8 0.8 0.5 ;  2 glass -1  0.2 0.5 0.6  0.5 ; }  2 blue 1  1 0 -2  0.6 ;", glass),
      with_floor("[ :my -1 :ry 25 t ; ] [ :mx 1.3 :rz 90 -2  0 1 1  0.6 0.5 0.4  4 ; t ; ]") +
          "obj t [ 16 red 1  0 0.55 0  0.6 0.05 0.4 ; [ :mx 0.5 l ; ] [ :mx -0.5 l ; ] ]\n"
          "obj l [ 15 blue 1  0 0 0  0 1 0  0.08 0.5 ; ]\n",
      with_floor("20 :mx 0.3 :ry 35 :sy 0.8 red 1 < p 1 -0.7 -0.2 -0.7  p 2 0.7 -0.2 -0.7  p 3 0.7 -0.2 0.7  p 4 -0.7 -0.2 0.7"
                 "  p 9 0 1.2 0  P 4 3 9 ; s  P 3 2 9 ; s c blue  P 2 1 9 ;  P 1 4 9 ;  P 1 2 3 4 ; > ;"),
  };
  const std::string dir = temp_dir();
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    INFO("scene " << i << ":\n" << scenes[i]);
    const std::string name = "s" + std::to_string(i);
    write(dir + "/" + name + ".ray", scenes[i]);
    const Run host = run(std::string(MINRT_BIN) + " -q --precision float --shims portable -o " + name + "-host.png " + name + ".ray", dir);
    const Run board = run(std::string(MINRT_SEND_BIN) + " --sim " + name + ".ray -o " + name + "-board.png", dir);
    INFO(host.err << board.err);
    REQUIRE(host.status == 0);
    REQUIRE(board.status == 0);
    const std::string a = minrt::test::read_file(dir + "/" + name + "-host.png");
    CHECK(a.size() > 300);  // a whole PNG
    CHECK(a == minrt::test::read_file(dir + "/" + name + "-board.png"));
  }
}
