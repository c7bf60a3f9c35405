/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for bias_forces() of
 * generated/spatial/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: fc72cb3c8cf4b7a874aa31d3d22b4faa3abbf00a501dc82f5b5c9e41e805f09d
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp2_bias_forces_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_sp2_bias_forces_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_bias_forces_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_bias_forces_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {8, 1, 1};
static const casadi_int casadi_s2[3] = {120, 1, 1};

/* snakecg_sp2_bias_forces:(q[9],v[8],K[120])->(h[8]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85;
  a00=arg[2]? arg[2][1] : 0;
  a01=arg[1]? arg[1][2] : 0;
  a02=arg[1]? arg[1][4] : 0;
  a03=(a01*a02);
  a04=arg[1]? arg[1][1] : 0;
  a05=arg[1]? arg[1][5] : 0;
  a06=(a04*a05);
  a03=(a03-a06);
  a06=arg[2]? arg[2][88] : 0;
  a07=arg[1]? arg[1][3] : 0;
  a08=(a06*a07);
  a09=arg[2]? arg[2][87] : 0;
  a10=(a09*a02);
  a08=(a08-a10);
  a10=(a08*a02);
  a10=(a03+a10);
  a11=(a09*a05);
  a12=arg[2]? arg[2][89] : 0;
  a13=(a12*a07);
  a11=(a11-a13);
  a13=(a11*a05);
  a10=(a10-a13);
  a13=arg[2]? arg[2][76] : 0;
  a14=arg[2]? arg[2][98] : 0;
  a15=(a13*a14);
  a16=arg[2]? arg[2][70] : 0;
  a17=arg[0]? arg[0][7] : 0;
  a18=cos(a17);
  a19=(a16*a18);
  a20=arg[2]? arg[2][73] : 0;
  a17=sin(a17);
  a21=(a20*a17);
  a19=(a19+a21);
  a21=arg[2]? arg[2][96] : 0;
  a22=(a19*a21);
  a15=(a15+a22);
  a20=(a20*a18);
  a16=(a16*a17);
  a20=(a20-a16);
  a16=arg[2]? arg[2][97] : 0;
  a22=(a20*a16);
  a15=(a15+a22);
  a22=arg[2]? arg[2][75] : 0;
  a23=arg[1]? arg[1][6] : 0;
  a24=(a22*a23);
  a24=(a07+a24);
  a25=(a15*a24);
  a26=(a22*a14);
  a27=arg[2]? arg[2][69] : 0;
  a28=(a27*a18);
  a29=arg[2]? arg[2][72] : 0;
  a30=(a29*a17);
  a28=(a28+a30);
  a30=(a28*a21);
  a26=(a26+a30);
  a29=(a29*a18);
  a27=(a27*a17);
  a29=(a29-a27);
  a27=(a29*a16);
  a26=(a26+a27);
  a27=(a13*a23);
  a27=(a02+a27);
  a30=(a26*a27);
  a25=(a25-a30);
  a30=(a25*a27);
  a30=(a10+a30);
  a31=(a22*a05);
  a32=arg[2]? arg[2][77] : 0;
  a33=(a32*a07);
  a31=(a31-a33);
  a31=(a23*a31);
  a14=(a32*a14);
  a33=arg[2]? arg[2][71] : 0;
  a34=(a33*a18);
  a35=arg[2]? arg[2][74] : 0;
  a36=(a35*a17);
  a34=(a34+a36);
  a21=(a34*a21);
  a14=(a14+a21);
  a35=(a35*a18);
  a33=(a33*a17);
  a35=(a35-a33);
  a16=(a35*a16);
  a14=(a14+a16);
  a16=(a31*a14);
  a30=(a30+a16);
  a16=(a32*a23);
  a16=(a05+a16);
  a33=(a26*a16);
  a17=(a14*a24);
  a33=(a33-a17);
  a17=(a33*a16);
  a30=(a30-a17);
  a17=(a13*a07);
  a18=(a22*a02);
  a17=(a17-a18);
  a17=(a23*a17);
  a18=(a17*a15);
  a30=(a30-a18);
  a18=1.;
  a21=-2.;
  a36=arg[0]? arg[0][4] : 0;
  a37=casadi_sq(a36);
  a37=(a21*a37);
  a38=(a18+a37);
  a39=arg[0]? arg[0][5] : 0;
  a40=casadi_sq(a39);
  a40=(a21*a40);
  a38=(a38+a40);
  a41=arg[2]? arg[2][48] : 0;
  a38=(a38*a41);
  a42=arg[0]? arg[0][6] : 0;
  a43=(2.*a42);
  a44=(a43*a39);
  a45=arg[0]? arg[0][3] : 0;
  a46=(2.*a45);
  a47=(a46*a36);
  a44=(a44+a47);
  a48=arg[2]? arg[2][49] : 0;
  a44=(a44*a48);
  a38=(a38+a44);
  a42=(a21*a42);
  a44=(a42*a36);
  a46=(a46*a39);
  a44=(a44+a46);
  a49=arg[2]? arg[2][50] : 0;
  a44=(a44*a49);
  a38=(a38+a44);
  a30=(a30-a38);
  a30=(a00*a30);
  a44=arg[2]? arg[2][2] : 0;
  a50=arg[2]? arg[2][92] : 0;
  a51=(a32*a50);
  a52=arg[2]? arg[2][90] : 0;
  a53=(a34*a52);
  a51=(a51+a53);
  a53=arg[2]? arg[2][91] : 0;
  a54=(a35*a53);
  a51=(a51+a54);
  a54=(a31*a51);
  a10=(a10+a54);
  a54=(a13*a50);
  a55=(a19*a52);
  a54=(a54+a55);
  a55=(a20*a53);
  a54=(a54+a55);
  a55=(a54*a24);
  a50=(a22*a50);
  a52=(a28*a52);
  a50=(a50+a52);
  a53=(a29*a53);
  a50=(a50+a53);
  a53=(a50*a27);
  a55=(a55-a53);
  a53=(a27*a55);
  a10=(a10+a53);
  a53=(a17*a54);
  a10=(a10-a53);
  a53=(a50*a16);
  a52=(a51*a24);
  a53=(a53-a52);
  a52=(a16*a53);
  a10=(a10-a52);
  a52=arg[2]? arg[2][86] : 0;
  a56=(a13*a52);
  a57=arg[2]? arg[2][84] : 0;
  a58=(a57*a19);
  a56=(a56+a58);
  a58=arg[2]? arg[2][85] : 0;
  a59=(a58*a20);
  a56=(a56+a59);
  a59=arg[2]? arg[2][101] : 0;
  a60=(a56*a59);
  a61=arg[2]? arg[2][80] : 0;
  a62=(a13*a61);
  a63=arg[2]? arg[2][78] : 0;
  a64=(a63*a19);
  a62=(a62+a64);
  a64=arg[2]? arg[2][79] : 0;
  a65=(a64*a20);
  a62=(a62+a65);
  a65=arg[0]? arg[0][8] : 0;
  a66=cos(a65);
  a67=(a62*a66);
  a68=arg[2]? arg[2][83] : 0;
  a69=(a13*a68);
  a70=arg[2]? arg[2][81] : 0;
  a71=(a70*a19);
  a69=(a69+a71);
  a71=arg[2]? arg[2][82] : 0;
  a72=(a71*a20);
  a69=(a69+a72);
  a65=sin(a65);
  a72=(a69*a65);
  a67=(a67+a72);
  a72=arg[2]? arg[2][99] : 0;
  a73=(a67*a72);
  a60=(a60+a73);
  a69=(a69*a66);
  a62=(a62*a65);
  a69=(a69-a62);
  a62=arg[2]? arg[2][100] : 0;
  a73=(a69*a62);
  a60=(a60+a73);
  a73=(a22*a52);
  a74=(a57*a28);
  a73=(a73+a74);
  a74=(a58*a29);
  a73=(a73+a74);
  a74=arg[1]? arg[1][7] : 0;
  a75=(a73*a74);
  a75=(a24+a75);
  a76=(a60*a75);
  a77=(a73*a59);
  a78=(a22*a61);
  a79=(a63*a28);
  a78=(a78+a79);
  a79=(a64*a29);
  a78=(a78+a79);
  a79=(a78*a66);
  a80=(a22*a68);
  a81=(a70*a28);
  a80=(a80+a81);
  a81=(a71*a29);
  a80=(a80+a81);
  a81=(a80*a65);
  a79=(a79+a81);
  a81=(a79*a72);
  a77=(a77+a81);
  a80=(a80*a66);
  a78=(a78*a65);
  a80=(a80-a78);
  a78=(a80*a62);
  a77=(a77+a78);
  a78=(a56*a74);
  a78=(a27+a78);
  a81=(a77*a78);
  a76=(a76-a81);
  a81=(a76*a78);
  a10=(a10+a81);
  a81=(a73*a16);
  a52=(a32*a52);
  a57=(a57*a34);
  a52=(a52+a57);
  a58=(a58*a35);
  a52=(a52+a58);
  a58=(a52*a24);
  a81=(a81-a58);
  a81=(a74*a81);
  a81=(a31+a81);
  a59=(a52*a59);
  a61=(a32*a61);
  a63=(a63*a34);
  a61=(a61+a63);
  a64=(a64*a35);
  a61=(a61+a64);
  a64=(a61*a66);
  a68=(a32*a68);
  a70=(a70*a34);
  a68=(a68+a70);
  a71=(a71*a35);
  a68=(a68+a71);
  a71=(a68*a65);
  a64=(a64+a71);
  a72=(a64*a72);
  a59=(a59+a72);
  a68=(a68*a66);
  a61=(a61*a65);
  a68=(a68-a61);
  a62=(a68*a62);
  a59=(a59+a62);
  a62=(a81*a59);
  a10=(a10+a62);
  a62=(a52*a74);
  a62=(a16+a62);
  a61=(a77*a62);
  a65=(a59*a75);
  a61=(a61-a65);
  a65=(a61*a62);
  a10=(a10-a65);
  a65=(a56*a24);
  a66=(a73*a27);
  a65=(a65-a66);
  a65=(a74*a65);
  a65=(a17+a65);
  a66=(a65*a60);
  a10=(a10-a66);
  a10=(a10-a38);
  a10=(a44*a10);
  a66=(a30+a10);
  a72=arg[2]? arg[2][0] : 0;
  a71=arg[2]? arg[2][94] : 0;
  a70=(a71*a07);
  a63=arg[2]? arg[2][93] : 0;
  a58=(a63*a02);
  a70=(a70-a58);
  a58=(a70*a02);
  a03=(a03+a58);
  a58=(a63*a05);
  a57=arg[2]? arg[2][95] : 0;
  a82=(a57*a07);
  a58=(a58-a82);
  a82=(a58*a05);
  a03=(a03-a82);
  a03=(a03-a38);
  a03=(a72*a03);
  a38=(a66+a03);
  if (res[0]!=0) res[0][0]=a38;
  a38=arg[1]? arg[1][0] : 0;
  a82=(a38*a05);
  a01=(a01*a07);
  a82=(a82-a01);
  a01=(a12*a02);
  a83=(a06*a05);
  a01=(a01-a83);
  a83=(a01*a05);
  a83=(a82+a83);
  a08=(a08*a07);
  a83=(a83-a08);
  a08=(a14*a27);
  a84=(a15*a16);
  a08=(a08-a84);
  a84=(a08*a16);
  a84=(a83+a84);
  a85=(a17*a26);
  a84=(a84+a85);
  a25=(a25*a24);
  a84=(a84-a25);
  a25=(a32*a02);
  a85=(a13*a05);
  a25=(a25-a85);
  a23=(a23*a25);
  a25=(a23*a14);
  a84=(a84-a25);
  a25=(a42*a39);
  a25=(a25+a47);
  a25=(a25*a41);
  a47=casadi_sq(a45);
  a21=(a21*a47);
  a18=(a18+a21);
  a40=(a18+a40);
  a40=(a40*a48);
  a25=(a25+a40);
  a40=(a43*a45);
  a21=(2.*a36);
  a21=(a21*a39);
  a40=(a40+a21);
  a40=(a40*a49);
  a25=(a25+a40);
  a84=(a84-a25);
  a84=(a00*a84);
  a40=(a17*a50);
  a83=(a83+a40);
  a40=(a51*a27);
  a39=(a54*a16);
  a40=(a40-a39);
  a39=(a16*a40);
  a83=(a83+a39);
  a39=(a23*a51);
  a83=(a83-a39);
  a55=(a24*a55);
  a83=(a83-a55);
  a55=(a59*a78);
  a39=(a60*a62);
  a55=(a55-a39);
  a39=(a55*a62);
  a83=(a83+a39);
  a39=(a65*a77);
  a83=(a83+a39);
  a76=(a76*a75);
  a83=(a83-a76);
  a76=(a52*a27);
  a39=(a56*a16);
  a76=(a76-a39);
  a74=(a74*a76);
  a74=(a23+a74);
  a76=(a74*a59);
  a83=(a83-a76);
  a83=(a83-a25);
  a83=(a44*a83);
  a76=(a84+a83);
  a39=(a57*a02);
  a47=(a71*a05);
  a39=(a39-a47);
  a47=(a39*a05);
  a82=(a82+a47);
  a70=(a70*a07);
  a82=(a82-a70);
  a82=(a82-a25);
  a82=(a72*a82);
  a25=(a76+a82);
  if (res[0]!=0) res[0][1]=a25;
  a04=(a04*a07);
  a38=(a38*a02);
  a04=(a04-a38);
  a11=(a11*a07);
  a11=(a04+a11);
  a01=(a01*a02);
  a11=(a11-a01);
  a33=(a33*a24);
  a33=(a11+a33);
  a01=(a23*a15);
  a33=(a33+a01);
  a08=(a08*a27);
  a33=(a33-a08);
  a08=(a31*a26);
  a33=(a33-a08);
  a43=(a43*a36);
  a43=(a43+a46);
  a43=(a43*a41);
  a42=(a42*a45);
  a42=(a42+a21);
  a42=(a42*a48);
  a43=(a43+a42);
  a18=(a18+a37);
  a18=(a18*a49);
  a43=(a43+a18);
  a33=(a33-a43);
  a00=(a00*a33);
  a33=(a23*a54);
  a11=(a11+a33);
  a53=(a24*a53);
  a11=(a11+a53);
  a53=(a31*a50);
  a11=(a11-a53);
  a40=(a27*a40);
  a11=(a11-a40);
  a61=(a61*a75);
  a11=(a11+a61);
  a61=(a74*a60);
  a11=(a11+a61);
  a55=(a55*a78);
  a11=(a11-a55);
  a55=(a81*a77);
  a11=(a11-a55);
  a11=(a11-a43);
  a44=(a44*a11);
  a11=(a00+a44);
  a58=(a58*a07);
  a04=(a04+a58);
  a39=(a39*a02);
  a04=(a04-a39);
  a04=(a04-a43);
  a72=(a72*a04);
  a04=(a11+a72);
  if (res[0]!=0) res[0][2]=a04;
  a04=arg[2]? arg[2][116] : 0;
  a43=(a73*a04);
  a39=arg[2]? arg[2][118] : 0;
  a58=(a39*a79);
  a43=(a43+a58);
  a58=arg[2]? arg[2][119] : 0;
  a55=(a58*a80);
  a43=(a43+a55);
  a55=(a73*a43);
  a61=(a73*a39);
  a40=arg[2]? arg[2][114] : 0;
  a53=(a40*a79);
  a61=(a61+a53);
  a53=arg[2]? arg[2][117] : 0;
  a33=(a53*a80);
  a61=(a61+a33);
  a33=(a79*a61);
  a55=(a55+a33);
  a33=(a73*a58);
  a79=(a53*a79);
  a33=(a33+a79);
  a79=arg[2]? arg[2][115] : 0;
  a18=(a79*a80);
  a33=(a33+a18);
  a80=(a80*a33);
  a55=(a55+a80);
  a80=(a55*a74);
  a18=(a56*a43);
  a49=(a67*a61);
  a18=(a18+a49);
  a49=(a69*a33);
  a18=(a18+a49);
  a49=(a18*a81);
  a80=(a80+a49);
  a43=(a52*a43);
  a61=(a64*a61);
  a43=(a43+a61);
  a33=(a68*a33);
  a43=(a43+a33);
  a33=(a43*a65);
  a80=(a80+a33);
  a33=(a43*a75);
  a61=(a56*a04);
  a49=(a39*a67);
  a61=(a61+a49);
  a49=(a58*a69);
  a61=(a61+a49);
  a49=(a52*a61);
  a37=(a56*a39);
  a42=(a40*a67);
  a37=(a37+a42);
  a42=(a53*a69);
  a37=(a37+a42);
  a42=(a64*a37);
  a49=(a49+a42);
  a42=(a56*a58);
  a48=(a53*a67);
  a42=(a42+a48);
  a48=(a79*a69);
  a42=(a42+a48);
  a48=(a68*a42);
  a49=(a49+a48);
  a48=(a49*a78);
  a33=(a33+a48);
  a04=(a52*a04);
  a48=(a39*a64);
  a04=(a04+a48);
  a48=(a58*a68);
  a04=(a04+a48);
  a04=(a52*a04);
  a39=(a52*a39);
  a40=(a40*a64);
  a39=(a39+a40);
  a40=(a53*a68);
  a39=(a39+a40);
  a39=(a64*a39);
  a04=(a04+a39);
  a58=(a52*a58);
  a53=(a53*a64);
  a58=(a58+a53);
  a79=(a79*a68);
  a58=(a58+a79);
  a68=(a68*a58);
  a04=(a04+a68);
  a68=(a04*a62);
  a33=(a33+a68);
  a68=(a33*a78);
  a80=(a80+a68);
  a54=(a54+a06);
  a60=(a60+a54);
  a68=(a60*a44);
  a80=(a80+a68);
  a68=(a18*a75);
  a61=(a56*a61);
  a67=(a67*a37);
  a61=(a61+a67);
  a69=(a69*a42);
  a61=(a61+a69);
  a69=(a61*a78);
  a68=(a68+a69);
  a69=(a49*a62);
  a68=(a68+a69);
  a69=(a68*a62);
  a80=(a80-a69);
  a51=(a51+a12);
  a59=(a59+a51);
  a69=(a59*a83);
  a80=(a80-a69);
  a69=arg[2]? arg[2][112] : 0;
  a42=(a69*a28);
  a67=arg[2]? arg[2][113] : 0;
  a37=(a67*a29);
  a42=(a42+a37);
  a37=arg[2]? arg[2][110] : 0;
  a58=(a37*a22);
  a42=(a42+a58);
  a58=(a22*a42);
  a79=arg[2]? arg[2][108] : 0;
  a53=(a79*a28);
  a64=arg[2]? arg[2][111] : 0;
  a39=(a64*a29);
  a53=(a53+a39);
  a39=(a69*a22);
  a53=(a53+a39);
  a39=(a28*a53);
  a58=(a58+a39);
  a28=(a64*a28);
  a39=arg[2]? arg[2][109] : 0;
  a40=(a39*a29);
  a28=(a28+a40);
  a40=(a67*a22);
  a28=(a28+a40);
  a29=(a29*a28);
  a58=(a58+a29);
  a29=(a58*a23);
  a29=(a80+a29);
  a40=(a13*a42);
  a48=(a19*a53);
  a40=(a40+a48);
  a48=(a20*a28);
  a40=(a40+a48);
  a48=(a40*a31);
  a29=(a29+a48);
  a42=(a32*a42);
  a53=(a34*a53);
  a42=(a42+a53);
  a28=(a35*a28);
  a42=(a42+a28);
  a28=(a42*a17);
  a29=(a29+a28);
  a28=(a42*a24);
  a53=(a69*a19);
  a48=(a67*a20);
  a53=(a53+a48);
  a48=(a37*a13);
  a53=(a53+a48);
  a48=(a32*a53);
  a21=(a79*a19);
  a45=(a64*a20);
  a21=(a21+a45);
  a45=(a69*a13);
  a21=(a21+a45);
  a45=(a34*a21);
  a48=(a48+a45);
  a45=(a64*a19);
  a41=(a39*a20);
  a45=(a45+a41);
  a41=(a67*a13);
  a45=(a45+a41);
  a41=(a35*a45);
  a48=(a48+a41);
  a41=(a48*a27);
  a28=(a28+a41);
  a41=(a69*a34);
  a46=(a67*a35);
  a41=(a41+a46);
  a37=(a37*a32);
  a41=(a41+a37);
  a41=(a32*a41);
  a79=(a79*a34);
  a37=(a64*a35);
  a79=(a79+a37);
  a69=(a69*a32);
  a79=(a79+a69);
  a79=(a34*a79);
  a41=(a41+a79);
  a64=(a64*a34);
  a39=(a39*a35);
  a64=(a64+a39);
  a67=(a67*a32);
  a64=(a64+a67);
  a35=(a35*a64);
  a41=(a41+a35);
  a35=(a41*a16);
  a28=(a28+a35);
  a35=(a28*a27);
  a29=(a29+a35);
  a15=(a15+a06);
  a35=(a15*a00);
  a29=(a29+a35);
  a35=(a40*a24);
  a53=(a13*a53);
  a19=(a19*a21);
  a53=(a53+a19);
  a20=(a20*a45);
  a53=(a53+a20);
  a20=(a53*a27);
  a35=(a35+a20);
  a20=(a48*a16);
  a35=(a35+a20);
  a20=(a35*a16);
  a29=(a29-a20);
  a14=(a14+a12);
  a20=(a14*a84);
  a29=(a29-a20);
  a20=arg[2]? arg[2][106] : 0;
  a45=(a20*a07);
  a19=arg[2]? arg[2][107] : 0;
  a21=(a19*a02);
  a45=(a45+a21);
  a21=arg[2]? arg[2][104] : 0;
  a21=(a21*a05);
  a45=(a45+a21);
  a21=(a45*a02);
  a21=(a29+a21);
  a64=(a71*a72);
  a21=(a21+a64);
  a64=arg[2]? arg[2][105] : 0;
  a67=(a64*a07);
  a39=arg[2]? arg[2][103] : 0;
  a39=(a39*a02);
  a67=(a67+a39);
  a19=(a19*a05);
  a67=(a67+a19);
  a19=(a67*a05);
  a21=(a21-a19);
  a19=(a57*a82);
  a21=(a21-a19);
  if (res[0]!=0) res[0][3]=a21;
  a21=(a18*a74);
  a61=(a61*a81);
  a21=(a21+a61);
  a61=(a49*a65);
  a21=(a21+a61);
  a55=(a55*a75);
  a18=(a18*a78);
  a55=(a55+a18);
  a18=(a43*a62);
  a55=(a55+a18);
  a62=(a55*a62);
  a21=(a21+a62);
  a59=(a59*a10);
  a21=(a21+a59);
  a33=(a33*a75);
  a21=(a21-a33);
  a50=(a50+a09);
  a77=(a77+a50);
  a33=(a77*a44);
  a21=(a21-a33);
  a33=(a40*a23);
  a33=(a21+a33);
  a53=(a53*a31);
  a33=(a33+a53);
  a53=(a48*a17);
  a33=(a33+a53);
  a58=(a58*a24);
  a40=(a40*a27);
  a58=(a58+a40);
  a40=(a42*a16);
  a58=(a58+a40);
  a16=(a58*a16);
  a33=(a33+a16);
  a14=(a14*a30);
  a33=(a33+a14);
  a28=(a28*a24);
  a33=(a33-a28);
  a26=(a26+a09);
  a00=(a26*a00);
  a33=(a33-a00);
  a00=arg[2]? arg[2][102] : 0;
  a00=(a00*a07);
  a64=(a64*a02);
  a00=(a00+a64);
  a20=(a20*a05);
  a00=(a00+a20);
  a05=(a00*a05);
  a05=(a33+a05);
  a57=(a57*a03);
  a05=(a05+a57);
  a45=(a45*a07);
  a05=(a05-a45);
  a72=(a63*a72);
  a05=(a05-a72);
  if (res[0]!=0) res[0][4]=a05;
  a43=(a43*a74);
  a49=(a49*a81);
  a43=(a43+a49);
  a04=(a04*a65);
  a43=(a43+a04);
  a68=(a68*a75);
  a43=(a43+a68);
  a77=(a77*a83);
  a43=(a43+a77);
  a55=(a55*a78);
  a43=(a43-a55);
  a60=(a60*a10);
  a43=(a43-a60);
  a42=(a42*a23);
  a42=(a43+a42);
  a48=(a48*a31);
  a42=(a42+a48);
  a41=(a41*a17);
  a42=(a42+a41);
  a35=(a35*a24);
  a42=(a42+a35);
  a26=(a26*a84);
  a42=(a42+a26);
  a58=(a58*a27);
  a42=(a42-a58);
  a15=(a15*a30);
  a42=(a42-a15);
  a67=(a67*a07);
  a67=(a42+a67);
  a63=(a63*a82);
  a67=(a67+a63);
  a00=(a00*a02);
  a67=(a67-a00);
  a71=(a71*a03);
  a67=(a67-a71);
  if (res[0]!=0) res[0][5]=a67;
  a67=(a32*a06);
  a71=(a13*a12);
  a67=(a67-a71);
  a66=(a66*a67);
  a12=(a22*a12);
  a67=(a32*a09);
  a12=(a12-a67);
  a76=(a76*a12);
  a66=(a66+a76);
  a09=(a13*a09);
  a06=(a22*a06);
  a09=(a09-a06);
  a11=(a11*a09);
  a66=(a66+a11);
  a29=(a29*a22);
  a66=(a66+a29);
  a33=(a33*a13);
  a66=(a66+a33);
  a42=(a42*a32);
  a66=(a66+a42);
  if (res[0]!=0) res[0][6]=a66;
  a80=(a73*a80);
  a21=(a56*a21);
  a80=(a80+a21);
  a43=(a52*a43);
  a80=(a80+a43);
  a43=(a52*a54);
  a21=(a56*a51);
  a43=(a43-a21);
  a10=(a10*a43);
  a80=(a80+a10);
  a51=(a73*a51);
  a52=(a52*a50);
  a51=(a51-a52);
  a83=(a83*a51);
  a80=(a80+a83);
  a56=(a56*a50);
  a73=(a73*a54);
  a56=(a56-a73);
  a44=(a44*a56);
  a80=(a80+a44);
  if (res[0]!=0) res[0][7]=a80;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_bias_forces(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_bias_forces_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_bias_forces_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_bias_forces_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_bias_forces_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_bias_forces_n_in(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_bias_forces_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_bias_forces_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_bias_forces_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_bias_forces_name_out(casadi_int i) {
  switch (i) {
    case 0: return "h";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_bias_forces_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_bias_forces_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_bias_forces_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_bias_forces_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 3*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

/* Cosines and sines of a block of angles in one loop without calls or branches, which the
 * compiler turns into vector instructions (16 angles per call): the sines and cosines of
 * the angles of 16 samples are computed at once, then the function without its own calls
 * runs per sample.
 * Reduction by pi/2 in three parts (Cody and Waite, exact products for |x| < 2^20 pi/2) and
 * fdlibm's polynomials of sin and cos on [-pi/4, pi/4] (errors below one unit in the last
 * place there); the quadrant turns the pair by n pi/2 with factors 0, +1, -1 (exact). An
 * angle with |x| above SNAKECG_SINCOS_MAX, or not a number, is left to the C library
 * (snakecg_sincos_large). */
#define SNAKECG_SINCOS_BLOCK 16
#define SNAKECG_SINCOS_MAX 8.0e5

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 6 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 (four angles per instruction), chosen at load time */
__attribute__((target_clones("avx2", "default")))
#endif
static void snakecg_sincos_block(const casadi_real* restrict x, casadi_real* restrict c,
                                 casadi_real* restrict s) {
  const casadi_real round = 6755399441055744.0; /* 1.5 * 2^52: adding it rounds to integers */
  const casadi_real two_over_pi = 6.36619772367581382433e-01;
  const casadi_real pio2_1 = 1.57079632673412561417e+00; /* pi/2: first 33 bits */
  const casadi_real pio2_2 = 6.07710050630396597660e-11; /* next 33 bits */
  const casadi_real pio2_3 = 2.02226624871116645580e-21; /* the rest */
  const casadi_real S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
      S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
      S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const casadi_real C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
      C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
      C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  int i;
  for (i = 0; i < SNAKECG_SINCOS_BLOCK; ++i) {
    casadi_real n = (x[i] * two_over_pi + round) - round;  /* nearest multiple of pi/2 */
    casadi_real m = n - 4.0 * ((0.25 * n + round) - round); /* n mod 4 in -2..2 */
    casadi_real am = fabs(m);
    casadi_real cq = 1.0 - am, sq = m * (2.0 - am);          /* cos, sin of n pi/2 */
    casadi_real y = ((x[i] - n * pio2_1) - n * pio2_2) - n * pio2_3;
    casadi_real z = y * y;
    casadi_real sy = y + z * y * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)))));
    casadi_real hz = 0.5 * z, w = 1.0 - hz;
    casadi_real cy = w + (((1.0 - w) - hz)
                          + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))))));
    c[i] = cy * cq - sy * sq;
    s[i] = sy * cq + cy * sq;
  }
}

/* the C library's cos and sin where |x| > SNAKECG_SINCOS_MAX or x is not a number (the
 * driver calls this only when it met such an angle while gathering them) */
static void snakecg_sincos_large(const casadi_real* x, casadi_real* c, casadi_real* s,
                                 casadi_int n) {
  casadi_int i;
  for (i = 0; i < n; ++i) {
    if (!(fabs(x[i]) <= SNAKECG_SINCOS_MAX)) {
      c[i] = cos(x[i]);
      s[i] = sin(x[i]);
    }
  }
}

/* snakecg_sp2_bias_forces_sincos: 816 CasADi instructions, printed one per line */
static void snakecg_sp2_bias_forces_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58, w59;
  casadi_real w60, w61, w62, w63, w64, w65, w66, w67, w68, w69;
  casadi_real w70, w71, w72, w73, w74, w75, w76, w77, w78, w79;
  casadi_real w80, w81, w82, w83, w84, w85;
  w0 = arg2[1];
  w1 = arg1[2];
  w2 = arg1[4];
  w3 = w1 * w2;
  w4 = arg1[1];
  w5 = arg1[5];
  w6 = w4 * w5;
  w3 = w3 - w6;
  w6 = arg2[88];
  w7 = arg1[3];
  w8 = w6 * w7;
  w9 = arg2[87];
  w10 = w9 * w2;
  w8 = w8 - w10;
  w10 = w8 * w2;
  w10 = w3 + w10;
  w11 = w9 * w5;
  w12 = arg2[89];
  w13 = w12 * w7;
  w11 = w11 - w13;
  w13 = w11 * w5;
  w10 = w10 - w13;
  w13 = arg2[76];
  w14 = arg2[98];
  w15 = w13 * w14;
  w16 = arg2[70];
  w17 = arg3[0];
  w18 = w16 * w17;
  w19 = arg2[73];
  w20 = arg4[0];
  w21 = w19 * w20;
  w18 = w18 + w21;
  w21 = arg2[96];
  w22 = w18 * w21;
  w15 = w15 + w22;
  w19 = w19 * w17;
  w16 = w16 * w20;
  w19 = w19 - w16;
  w16 = arg2[97];
  w22 = w19 * w16;
  w15 = w15 + w22;
  w22 = arg2[75];
  w23 = arg1[6];
  w24 = w22 * w23;
  w24 = w7 + w24;
  w25 = w15 * w24;
  w26 = w22 * w14;
  w27 = arg2[69];
  w28 = w27 * w17;
  w29 = arg2[72];
  w30 = w29 * w20;
  w28 = w28 + w30;
  w30 = w28 * w21;
  w26 = w26 + w30;
  w29 = w29 * w17;
  w27 = w27 * w20;
  w29 = w29 - w27;
  w27 = w29 * w16;
  w26 = w26 + w27;
  w27 = w13 * w23;
  w27 = w2 + w27;
  w30 = w26 * w27;
  w25 = w25 - w30;
  w30 = w25 * w27;
  w30 = w10 + w30;
  w31 = w22 * w5;
  w32 = arg2[77];
  w33 = w32 * w7;
  w31 = w31 - w33;
  w31 = w23 * w31;
  w14 = w32 * w14;
  w33 = arg2[71];
  w34 = w33 * w17;
  w35 = arg2[74];
  w36 = w35 * w20;
  w34 = w34 + w36;
  w21 = w34 * w21;
  w14 = w14 + w21;
  w35 = w35 * w17;
  w33 = w33 * w20;
  w35 = w35 - w33;
  w16 = w35 * w16;
  w14 = w14 + w16;
  w16 = w31 * w14;
  w30 = w30 + w16;
  w16 = w32 * w23;
  w16 = w5 + w16;
  w33 = w26 * w16;
  w20 = w14 * w24;
  w33 = w33 - w20;
  w20 = w33 * w16;
  w30 = w30 - w20;
  w20 = w13 * w7;
  w17 = w22 * w2;
  w20 = w20 - w17;
  w20 = w23 * w20;
  w17 = w20 * w15;
  w30 = w30 - w17;
  w17 = 1.0;
  w21 = (-2.0);
  w36 = arg0[4];
  w37 = w36 * w36;
  w37 = w21 * w37;
  w38 = w17 + w37;
  w39 = arg0[5];
  w40 = w39 * w39;
  w40 = w21 * w40;
  w38 = w38 + w40;
  w41 = arg2[48];
  w38 = w38 * w41;
  w42 = arg0[6];
  w43 = w42 + w42;
  w44 = w43 * w39;
  w45 = arg0[3];
  w46 = w45 + w45;
  w47 = w46 * w36;
  w44 = w44 + w47;
  w48 = arg2[49];
  w44 = w44 * w48;
  w38 = w38 + w44;
  w42 = w21 * w42;
  w44 = w42 * w36;
  w46 = w46 * w39;
  w44 = w44 + w46;
  w49 = arg2[50];
  w44 = w44 * w49;
  w38 = w38 + w44;
  w30 = w30 - w38;
  w30 = w0 * w30;
  w44 = arg2[2];
  w50 = arg2[92];
  w51 = w32 * w50;
  w52 = arg2[90];
  w53 = w34 * w52;
  w51 = w51 + w53;
  w53 = arg2[91];
  w54 = w35 * w53;
  w51 = w51 + w54;
  w54 = w31 * w51;
  w10 = w10 + w54;
  w54 = w13 * w50;
  w55 = w18 * w52;
  w54 = w54 + w55;
  w55 = w19 * w53;
  w54 = w54 + w55;
  w55 = w54 * w24;
  w50 = w22 * w50;
  w52 = w28 * w52;
  w50 = w50 + w52;
  w53 = w29 * w53;
  w50 = w50 + w53;
  w53 = w50 * w27;
  w55 = w55 - w53;
  w53 = w27 * w55;
  w10 = w10 + w53;
  w53 = w20 * w54;
  w10 = w10 - w53;
  w53 = w50 * w16;
  w52 = w51 * w24;
  w53 = w53 - w52;
  w52 = w16 * w53;
  w10 = w10 - w52;
  w52 = arg2[86];
  w56 = w13 * w52;
  w57 = arg2[84];
  w58 = w57 * w18;
  w56 = w56 + w58;
  w58 = arg2[85];
  w59 = w58 * w19;
  w56 = w56 + w59;
  w59 = arg2[101];
  w60 = w56 * w59;
  w61 = arg2[80];
  w62 = w13 * w61;
  w63 = arg2[78];
  w64 = w63 * w18;
  w62 = w62 + w64;
  w64 = arg2[79];
  w65 = w64 * w19;
  w62 = w62 + w65;
  w65 = arg3[1];
  w66 = w62 * w65;
  w67 = arg2[83];
  w68 = w13 * w67;
  w69 = arg2[81];
  w70 = w69 * w18;
  w68 = w68 + w70;
  w70 = arg2[82];
  w71 = w70 * w19;
  w68 = w68 + w71;
  w71 = arg4[1];
  w72 = w68 * w71;
  w66 = w66 + w72;
  w72 = arg2[99];
  w73 = w66 * w72;
  w60 = w60 + w73;
  w68 = w68 * w65;
  w62 = w62 * w71;
  w68 = w68 - w62;
  w62 = arg2[100];
  w73 = w68 * w62;
  w60 = w60 + w73;
  w73 = w22 * w52;
  w74 = w57 * w28;
  w73 = w73 + w74;
  w74 = w58 * w29;
  w73 = w73 + w74;
  w74 = arg1[7];
  w75 = w73 * w74;
  w75 = w24 + w75;
  w76 = w60 * w75;
  w77 = w73 * w59;
  w78 = w22 * w61;
  w79 = w63 * w28;
  w78 = w78 + w79;
  w79 = w64 * w29;
  w78 = w78 + w79;
  w79 = w78 * w65;
  w80 = w22 * w67;
  w81 = w69 * w28;
  w80 = w80 + w81;
  w81 = w70 * w29;
  w80 = w80 + w81;
  w81 = w80 * w71;
  w79 = w79 + w81;
  w81 = w79 * w72;
  w77 = w77 + w81;
  w80 = w80 * w65;
  w78 = w78 * w71;
  w80 = w80 - w78;
  w78 = w80 * w62;
  w77 = w77 + w78;
  w78 = w56 * w74;
  w78 = w27 + w78;
  w81 = w77 * w78;
  w76 = w76 - w81;
  w81 = w76 * w78;
  w10 = w10 + w81;
  w81 = w73 * w16;
  w52 = w32 * w52;
  w57 = w57 * w34;
  w52 = w52 + w57;
  w58 = w58 * w35;
  w52 = w52 + w58;
  w58 = w52 * w24;
  w81 = w81 - w58;
  w81 = w74 * w81;
  w81 = w31 + w81;
  w59 = w52 * w59;
  w61 = w32 * w61;
  w63 = w63 * w34;
  w61 = w61 + w63;
  w64 = w64 * w35;
  w61 = w61 + w64;
  w64 = w61 * w65;
  w67 = w32 * w67;
  w69 = w69 * w34;
  w67 = w67 + w69;
  w70 = w70 * w35;
  w67 = w67 + w70;
  w70 = w67 * w71;
  w64 = w64 + w70;
  w72 = w64 * w72;
  w59 = w59 + w72;
  w67 = w67 * w65;
  w61 = w61 * w71;
  w67 = w67 - w61;
  w62 = w67 * w62;
  w59 = w59 + w62;
  w62 = w81 * w59;
  w10 = w10 + w62;
  w62 = w52 * w74;
  w62 = w16 + w62;
  w61 = w77 * w62;
  w71 = w59 * w75;
  w61 = w61 - w71;
  w71 = w61 * w62;
  w10 = w10 - w71;
  w71 = w56 * w24;
  w65 = w73 * w27;
  w71 = w71 - w65;
  w71 = w74 * w71;
  w71 = w20 + w71;
  w65 = w71 * w60;
  w10 = w10 - w65;
  w10 = w10 - w38;
  w10 = w44 * w10;
  w65 = w30 + w10;
  w72 = arg2[0];
  w70 = arg2[94];
  w69 = w70 * w7;
  w63 = arg2[93];
  w58 = w63 * w2;
  w69 = w69 - w58;
  w58 = w69 * w2;
  w3 = w3 + w58;
  w58 = w63 * w5;
  w57 = arg2[95];
  w82 = w57 * w7;
  w58 = w58 - w82;
  w82 = w58 * w5;
  w3 = w3 - w82;
  w3 = w3 - w38;
  w3 = w72 * w3;
  w38 = w65 + w3;
  res0[0] = w38;
  w38 = arg1[0];
  w82 = w38 * w5;
  w1 = w1 * w7;
  w82 = w82 - w1;
  w1 = w12 * w2;
  w83 = w6 * w5;
  w1 = w1 - w83;
  w83 = w1 * w5;
  w83 = w82 + w83;
  w8 = w8 * w7;
  w83 = w83 - w8;
  w8 = w14 * w27;
  w84 = w15 * w16;
  w8 = w8 - w84;
  w84 = w8 * w16;
  w84 = w83 + w84;
  w85 = w20 * w26;
  w84 = w84 + w85;
  w25 = w25 * w24;
  w84 = w84 - w25;
  w25 = w32 * w2;
  w85 = w13 * w5;
  w25 = w25 - w85;
  w23 = w23 * w25;
  w25 = w23 * w14;
  w84 = w84 - w25;
  w25 = w42 * w39;
  w25 = w25 + w47;
  w25 = w25 * w41;
  w47 = w45 * w45;
  w21 = w21 * w47;
  w17 = w17 + w21;
  w40 = w17 + w40;
  w40 = w40 * w48;
  w25 = w25 + w40;
  w40 = w43 * w45;
  w21 = w36 + w36;
  w21 = w21 * w39;
  w40 = w40 + w21;
  w40 = w40 * w49;
  w25 = w25 + w40;
  w84 = w84 - w25;
  w84 = w0 * w84;
  w40 = w20 * w50;
  w83 = w83 + w40;
  w40 = w51 * w27;
  w39 = w54 * w16;
  w40 = w40 - w39;
  w39 = w16 * w40;
  w83 = w83 + w39;
  w39 = w23 * w51;
  w83 = w83 - w39;
  w55 = w24 * w55;
  w83 = w83 - w55;
  w55 = w59 * w78;
  w39 = w60 * w62;
  w55 = w55 - w39;
  w39 = w55 * w62;
  w83 = w83 + w39;
  w39 = w71 * w77;
  w83 = w83 + w39;
  w76 = w76 * w75;
  w83 = w83 - w76;
  w76 = w52 * w27;
  w39 = w56 * w16;
  w76 = w76 - w39;
  w74 = w74 * w76;
  w74 = w23 + w74;
  w76 = w74 * w59;
  w83 = w83 - w76;
  w83 = w83 - w25;
  w83 = w44 * w83;
  w76 = w84 + w83;
  w39 = w57 * w2;
  w47 = w70 * w5;
  w39 = w39 - w47;
  w47 = w39 * w5;
  w82 = w82 + w47;
  w69 = w69 * w7;
  w82 = w82 - w69;
  w82 = w82 - w25;
  w82 = w72 * w82;
  w25 = w76 + w82;
  res0[1] = w25;
  w4 = w4 * w7;
  w38 = w38 * w2;
  w4 = w4 - w38;
  w11 = w11 * w7;
  w11 = w4 + w11;
  w1 = w1 * w2;
  w11 = w11 - w1;
  w33 = w33 * w24;
  w33 = w11 + w33;
  w1 = w23 * w15;
  w33 = w33 + w1;
  w8 = w8 * w27;
  w33 = w33 - w8;
  w8 = w31 * w26;
  w33 = w33 - w8;
  w43 = w43 * w36;
  w43 = w43 + w46;
  w43 = w43 * w41;
  w42 = w42 * w45;
  w42 = w42 + w21;
  w42 = w42 * w48;
  w43 = w43 + w42;
  w17 = w17 + w37;
  w17 = w17 * w49;
  w43 = w43 + w17;
  w33 = w33 - w43;
  w0 = w0 * w33;
  w33 = w23 * w54;
  w11 = w11 + w33;
  w53 = w24 * w53;
  w11 = w11 + w53;
  w53 = w31 * w50;
  w11 = w11 - w53;
  w40 = w27 * w40;
  w11 = w11 - w40;
  w61 = w61 * w75;
  w11 = w11 + w61;
  w61 = w74 * w60;
  w11 = w11 + w61;
  w55 = w55 * w78;
  w11 = w11 - w55;
  w55 = w81 * w77;
  w11 = w11 - w55;
  w11 = w11 - w43;
  w44 = w44 * w11;
  w11 = w0 + w44;
  w58 = w58 * w7;
  w4 = w4 + w58;
  w39 = w39 * w2;
  w4 = w4 - w39;
  w4 = w4 - w43;
  w72 = w72 * w4;
  w4 = w11 + w72;
  res0[2] = w4;
  w4 = arg2[116];
  w43 = w73 * w4;
  w39 = arg2[118];
  w58 = w39 * w79;
  w43 = w43 + w58;
  w58 = arg2[119];
  w55 = w58 * w80;
  w43 = w43 + w55;
  w55 = w73 * w43;
  w61 = w73 * w39;
  w40 = arg2[114];
  w53 = w40 * w79;
  w61 = w61 + w53;
  w53 = arg2[117];
  w33 = w53 * w80;
  w61 = w61 + w33;
  w33 = w79 * w61;
  w55 = w55 + w33;
  w33 = w73 * w58;
  w79 = w53 * w79;
  w33 = w33 + w79;
  w79 = arg2[115];
  w17 = w79 * w80;
  w33 = w33 + w17;
  w80 = w80 * w33;
  w55 = w55 + w80;
  w80 = w55 * w74;
  w17 = w56 * w43;
  w49 = w66 * w61;
  w17 = w17 + w49;
  w49 = w68 * w33;
  w17 = w17 + w49;
  w49 = w17 * w81;
  w80 = w80 + w49;
  w43 = w52 * w43;
  w61 = w64 * w61;
  w43 = w43 + w61;
  w33 = w67 * w33;
  w43 = w43 + w33;
  w33 = w43 * w71;
  w80 = w80 + w33;
  w33 = w43 * w75;
  w61 = w56 * w4;
  w49 = w39 * w66;
  w61 = w61 + w49;
  w49 = w58 * w68;
  w61 = w61 + w49;
  w49 = w52 * w61;
  w37 = w56 * w39;
  w42 = w40 * w66;
  w37 = w37 + w42;
  w42 = w53 * w68;
  w37 = w37 + w42;
  w42 = w64 * w37;
  w49 = w49 + w42;
  w42 = w56 * w58;
  w48 = w53 * w66;
  w42 = w42 + w48;
  w48 = w79 * w68;
  w42 = w42 + w48;
  w48 = w67 * w42;
  w49 = w49 + w48;
  w48 = w49 * w78;
  w33 = w33 + w48;
  w4 = w52 * w4;
  w48 = w39 * w64;
  w4 = w4 + w48;
  w48 = w58 * w67;
  w4 = w4 + w48;
  w4 = w52 * w4;
  w39 = w52 * w39;
  w40 = w40 * w64;
  w39 = w39 + w40;
  w40 = w53 * w67;
  w39 = w39 + w40;
  w39 = w64 * w39;
  w4 = w4 + w39;
  w58 = w52 * w58;
  w53 = w53 * w64;
  w58 = w58 + w53;
  w79 = w79 * w67;
  w58 = w58 + w79;
  w67 = w67 * w58;
  w4 = w4 + w67;
  w67 = w4 * w62;
  w33 = w33 + w67;
  w67 = w33 * w78;
  w80 = w80 + w67;
  w54 = w54 + w6;
  w60 = w60 + w54;
  w67 = w60 * w44;
  w80 = w80 + w67;
  w67 = w17 * w75;
  w61 = w56 * w61;
  w66 = w66 * w37;
  w61 = w61 + w66;
  w68 = w68 * w42;
  w61 = w61 + w68;
  w68 = w61 * w78;
  w67 = w67 + w68;
  w68 = w49 * w62;
  w67 = w67 + w68;
  w68 = w67 * w62;
  w80 = w80 - w68;
  w51 = w51 + w12;
  w59 = w59 + w51;
  w68 = w59 * w83;
  w80 = w80 - w68;
  w68 = arg2[112];
  w42 = w68 * w28;
  w66 = arg2[113];
  w37 = w66 * w29;
  w42 = w42 + w37;
  w37 = arg2[110];
  w58 = w37 * w22;
  w42 = w42 + w58;
  w58 = w22 * w42;
  w79 = arg2[108];
  w53 = w79 * w28;
  w64 = arg2[111];
  w39 = w64 * w29;
  w53 = w53 + w39;
  w39 = w68 * w22;
  w53 = w53 + w39;
  w39 = w28 * w53;
  w58 = w58 + w39;
  w28 = w64 * w28;
  w39 = arg2[109];
  w40 = w39 * w29;
  w28 = w28 + w40;
  w40 = w66 * w22;
  w28 = w28 + w40;
  w29 = w29 * w28;
  w58 = w58 + w29;
  w29 = w58 * w23;
  w29 = w80 + w29;
  w40 = w13 * w42;
  w48 = w18 * w53;
  w40 = w40 + w48;
  w48 = w19 * w28;
  w40 = w40 + w48;
  w48 = w40 * w31;
  w29 = w29 + w48;
  w42 = w32 * w42;
  w53 = w34 * w53;
  w42 = w42 + w53;
  w28 = w35 * w28;
  w42 = w42 + w28;
  w28 = w42 * w20;
  w29 = w29 + w28;
  w28 = w42 * w24;
  w53 = w68 * w18;
  w48 = w66 * w19;
  w53 = w53 + w48;
  w48 = w37 * w13;
  w53 = w53 + w48;
  w48 = w32 * w53;
  w21 = w79 * w18;
  w45 = w64 * w19;
  w21 = w21 + w45;
  w45 = w68 * w13;
  w21 = w21 + w45;
  w45 = w34 * w21;
  w48 = w48 + w45;
  w45 = w64 * w18;
  w41 = w39 * w19;
  w45 = w45 + w41;
  w41 = w66 * w13;
  w45 = w45 + w41;
  w41 = w35 * w45;
  w48 = w48 + w41;
  w41 = w48 * w27;
  w28 = w28 + w41;
  w41 = w68 * w34;
  w46 = w66 * w35;
  w41 = w41 + w46;
  w37 = w37 * w32;
  w41 = w41 + w37;
  w41 = w32 * w41;
  w79 = w79 * w34;
  w37 = w64 * w35;
  w79 = w79 + w37;
  w68 = w68 * w32;
  w79 = w79 + w68;
  w79 = w34 * w79;
  w41 = w41 + w79;
  w64 = w64 * w34;
  w39 = w39 * w35;
  w64 = w64 + w39;
  w66 = w66 * w32;
  w64 = w64 + w66;
  w35 = w35 * w64;
  w41 = w41 + w35;
  w35 = w41 * w16;
  w28 = w28 + w35;
  w35 = w28 * w27;
  w29 = w29 + w35;
  w15 = w15 + w6;
  w35 = w15 * w0;
  w29 = w29 + w35;
  w35 = w40 * w24;
  w53 = w13 * w53;
  w18 = w18 * w21;
  w53 = w53 + w18;
  w19 = w19 * w45;
  w53 = w53 + w19;
  w19 = w53 * w27;
  w35 = w35 + w19;
  w19 = w48 * w16;
  w35 = w35 + w19;
  w19 = w35 * w16;
  w29 = w29 - w19;
  w14 = w14 + w12;
  w19 = w14 * w84;
  w29 = w29 - w19;
  w19 = arg2[106];
  w45 = w19 * w7;
  w18 = arg2[107];
  w21 = w18 * w2;
  w45 = w45 + w21;
  w21 = arg2[104];
  w21 = w21 * w5;
  w45 = w45 + w21;
  w21 = w45 * w2;
  w21 = w29 + w21;
  w64 = w70 * w72;
  w21 = w21 + w64;
  w64 = arg2[105];
  w66 = w64 * w7;
  w39 = arg2[103];
  w39 = w39 * w2;
  w66 = w66 + w39;
  w18 = w18 * w5;
  w66 = w66 + w18;
  w18 = w66 * w5;
  w21 = w21 - w18;
  w18 = w57 * w82;
  w21 = w21 - w18;
  res0[3] = w21;
  w21 = w17 * w74;
  w61 = w61 * w81;
  w21 = w21 + w61;
  w61 = w49 * w71;
  w21 = w21 + w61;
  w55 = w55 * w75;
  w17 = w17 * w78;
  w55 = w55 + w17;
  w17 = w43 * w62;
  w55 = w55 + w17;
  w62 = w55 * w62;
  w21 = w21 + w62;
  w59 = w59 * w10;
  w21 = w21 + w59;
  w33 = w33 * w75;
  w21 = w21 - w33;
  w50 = w50 + w9;
  w77 = w77 + w50;
  w33 = w77 * w44;
  w21 = w21 - w33;
  w33 = w40 * w23;
  w33 = w21 + w33;
  w53 = w53 * w31;
  w33 = w33 + w53;
  w53 = w48 * w20;
  w33 = w33 + w53;
  w58 = w58 * w24;
  w40 = w40 * w27;
  w58 = w58 + w40;
  w40 = w42 * w16;
  w58 = w58 + w40;
  w16 = w58 * w16;
  w33 = w33 + w16;
  w14 = w14 * w30;
  w33 = w33 + w14;
  w28 = w28 * w24;
  w33 = w33 - w28;
  w26 = w26 + w9;
  w0 = w26 * w0;
  w33 = w33 - w0;
  w0 = arg2[102];
  w0 = w0 * w7;
  w64 = w64 * w2;
  w0 = w0 + w64;
  w19 = w19 * w5;
  w0 = w0 + w19;
  w5 = w0 * w5;
  w5 = w33 + w5;
  w57 = w57 * w3;
  w5 = w5 + w57;
  w45 = w45 * w7;
  w5 = w5 - w45;
  w72 = w63 * w72;
  w5 = w5 - w72;
  res0[4] = w5;
  w43 = w43 * w74;
  w49 = w49 * w81;
  w43 = w43 + w49;
  w4 = w4 * w71;
  w43 = w43 + w4;
  w67 = w67 * w75;
  w43 = w43 + w67;
  w77 = w77 * w83;
  w43 = w43 + w77;
  w55 = w55 * w78;
  w43 = w43 - w55;
  w60 = w60 * w10;
  w43 = w43 - w60;
  w42 = w42 * w23;
  w42 = w43 + w42;
  w48 = w48 * w31;
  w42 = w42 + w48;
  w41 = w41 * w20;
  w42 = w42 + w41;
  w35 = w35 * w24;
  w42 = w42 + w35;
  w26 = w26 * w84;
  w42 = w42 + w26;
  w58 = w58 * w27;
  w42 = w42 - w58;
  w15 = w15 * w30;
  w42 = w42 - w15;
  w66 = w66 * w7;
  w66 = w42 + w66;
  w63 = w63 * w82;
  w66 = w66 + w63;
  w0 = w0 * w2;
  w66 = w66 - w0;
  w70 = w70 * w3;
  w66 = w66 - w70;
  res0[5] = w66;
  w66 = w32 * w6;
  w70 = w13 * w12;
  w66 = w66 - w70;
  w65 = w65 * w66;
  w12 = w22 * w12;
  w66 = w32 * w9;
  w12 = w12 - w66;
  w76 = w76 * w12;
  w65 = w65 + w76;
  w9 = w13 * w9;
  w6 = w22 * w6;
  w9 = w9 - w6;
  w11 = w11 * w9;
  w65 = w65 + w11;
  w29 = w29 * w22;
  w65 = w65 + w29;
  w33 = w33 * w13;
  w65 = w65 + w33;
  w42 = w42 * w32;
  w65 = w65 + w42;
  res0[6] = w65;
  w80 = w73 * w80;
  w21 = w56 * w21;
  w80 = w80 + w21;
  w43 = w52 * w43;
  w80 = w80 + w43;
  w43 = w52 * w54;
  w21 = w56 * w51;
  w43 = w43 - w21;
  w10 = w10 * w43;
  w80 = w80 + w10;
  w51 = w73 * w51;
  w52 = w52 * w50;
  w51 = w51 - w52;
  w83 = w83 * w51;
  w80 = w80 + w83;
  w56 = w56 * w50;
  w73 = w73 * w54;
  w56 = w56 - w73;
  w44 = w44 * w56;
  w80 = w80 + w44;
  res0[7] = w80;
}


CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_bias_forces(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[3];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 87);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 3; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && res[0]) {
    /* cos and sin of q[7..8] of 16 samples at a time, then snakecg_sp2_bias_forces_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 2, per = 16;
    casadi_real ang[32], ca[32], sa[32];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 32; ++k) ang[k] = 0;
    for (i0 = 0; i0 < n; i0 += per) {
      m = n - i0 < per ? n - i0 : per;
      large = 0;
      for (i = 0; i < m; ++i) {
        const casadi_real* q = arg[0] + (i0 + i) * stride[0] + 7;
        for (k = 0; k < na; ++k) {
          ang[i * na + k] = q[k];
          large |= !(fabs(q[k]) <= SNAKECG_SINCOS_MAX);
        }
      }
      for (k = 0; k < m * na; k += SNAKECG_SINCOS_BLOCK) {
        snakecg_sincos_block(ang + k, ca + k, sa + k);
      }
      if (large) snakecg_sincos_large(ang, ca, sa, m * na);
      for (i = 0; i < m; ++i) {
        snakecg_sp2_bias_forces_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], ca + i * na, sa + i * na, res[0] + (i0 + i) * 8);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      r[0] = res[0] + i * 8;
      if (snakecg_sp2_bias_forces(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
