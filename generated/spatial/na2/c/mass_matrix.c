/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for mass_matrix() of
 * generated/spatial/na2/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: 24971844b370b327c8b1ec05d13793d7cad6a8e8fa0affc7182db4e83ce1513f
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp2_mass_matrix_ ## ID
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

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_sp2_mass_matrix_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_mass_matrix_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_mass_matrix_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {120, 1, 1};
static const casadi_int casadi_s2[3] = {8, 8, 1};

/* snakecg_sp2_mass_matrix:(q[9],K[120])->(M[8x8]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73;
  a00=arg[1]? arg[1][1] : 0;
  a01=arg[1]? arg[1][2] : 0;
  a02=(a00+a01);
  a03=arg[1]? arg[1][0] : 0;
  a04=(a02+a03);
  if (res[0]!=0) res[0][0]=a04;
  a05=0.;
  if (res[0]!=0) res[0][1]=a05;
  if (res[0]!=0) res[0][2]=a05;
  if (res[0]!=0) res[0][3]=a05;
  a06=arg[1]? arg[1][95] : 0;
  a07=(a06*a03);
  a08=arg[1]? arg[1][77] : 0;
  a09=arg[1]? arg[1][98] : 0;
  a10=(a08*a09);
  a11=arg[1]? arg[1][71] : 0;
  a12=arg[0]? arg[0][7] : 0;
  a13=cos(a12);
  a14=(a11*a13);
  a15=arg[1]? arg[1][74] : 0;
  a12=sin(a12);
  a16=(a15*a12);
  a14=(a14+a16);
  a16=arg[1]? arg[1][96] : 0;
  a17=(a14*a16);
  a10=(a10+a17);
  a15=(a15*a13);
  a11=(a11*a12);
  a15=(a15-a11);
  a11=arg[1]? arg[1][97] : 0;
  a17=(a15*a11);
  a10=(a10+a17);
  a17=arg[1]? arg[1][89] : 0;
  a10=(a10+a17);
  a18=(a10*a00);
  a19=arg[1]? arg[1][86] : 0;
  a20=(a08*a19);
  a21=arg[1]? arg[1][84] : 0;
  a22=(a21*a14);
  a20=(a20+a22);
  a22=arg[1]? arg[1][85] : 0;
  a23=(a22*a15);
  a20=(a20+a23);
  a23=arg[1]? arg[1][101] : 0;
  a24=(a20*a23);
  a25=arg[1]? arg[1][80] : 0;
  a26=(a08*a25);
  a27=arg[1]? arg[1][78] : 0;
  a28=(a27*a14);
  a26=(a26+a28);
  a28=arg[1]? arg[1][79] : 0;
  a29=(a28*a15);
  a26=(a26+a29);
  a29=arg[0]? arg[0][8] : 0;
  a30=cos(a29);
  a31=(a26*a30);
  a32=arg[1]? arg[1][83] : 0;
  a33=(a08*a32);
  a34=arg[1]? arg[1][81] : 0;
  a35=(a34*a14);
  a33=(a33+a35);
  a35=arg[1]? arg[1][82] : 0;
  a36=(a35*a15);
  a33=(a33+a36);
  a29=sin(a29);
  a36=(a33*a29);
  a31=(a31+a36);
  a36=arg[1]? arg[1][99] : 0;
  a37=(a31*a36);
  a24=(a24+a37);
  a33=(a33*a30);
  a26=(a26*a29);
  a33=(a33-a26);
  a26=arg[1]? arg[1][100] : 0;
  a37=(a33*a26);
  a24=(a24+a37);
  a37=arg[1]? arg[1][92] : 0;
  a38=(a08*a37);
  a39=arg[1]? arg[1][90] : 0;
  a40=(a14*a39);
  a38=(a38+a40);
  a40=arg[1]? arg[1][91] : 0;
  a41=(a15*a40);
  a38=(a38+a41);
  a38=(a38+a17);
  a24=(a24+a38);
  a41=(a24*a01);
  a42=(a18+a41);
  a43=(a07+a42);
  if (res[0]!=0) res[0][4]=a43;
  a44=arg[1]? arg[1][94] : 0;
  a45=(a44*a03);
  a46=arg[1]? arg[1][76] : 0;
  a47=(a46*a09);
  a48=arg[1]? arg[1][70] : 0;
  a49=(a48*a13);
  a50=arg[1]? arg[1][73] : 0;
  a51=(a50*a12);
  a49=(a49+a51);
  a51=(a49*a16);
  a47=(a47+a51);
  a50=(a50*a13);
  a48=(a48*a12);
  a50=(a50-a48);
  a48=(a50*a11);
  a47=(a47+a48);
  a48=arg[1]? arg[1][88] : 0;
  a47=(a47+a48);
  a51=(a47*a00);
  a52=(a46*a19);
  a53=(a21*a49);
  a52=(a52+a53);
  a53=(a22*a50);
  a52=(a52+a53);
  a53=(a52*a23);
  a54=(a46*a25);
  a55=(a27*a49);
  a54=(a54+a55);
  a55=(a28*a50);
  a54=(a54+a55);
  a55=(a54*a30);
  a56=(a46*a32);
  a57=(a34*a49);
  a56=(a56+a57);
  a57=(a35*a50);
  a56=(a56+a57);
  a57=(a56*a29);
  a55=(a55+a57);
  a57=(a55*a36);
  a53=(a53+a57);
  a56=(a56*a30);
  a54=(a54*a29);
  a56=(a56-a54);
  a54=(a56*a26);
  a53=(a53+a54);
  a54=(a46*a37);
  a57=(a49*a39);
  a54=(a54+a57);
  a57=(a50*a40);
  a54=(a54+a57);
  a54=(a54+a48);
  a53=(a53+a54);
  a57=(a53*a01);
  a58=(a51+a57);
  a59=(a45+a58);
  a60=(-a59);
  if (res[0]!=0) res[0][5]=a60;
  a61=(a46*a42);
  a62=(a08*a48);
  a63=(a46*a17);
  a62=(a62-a63);
  a63=(a02*a62);
  a61=(a61+a63);
  a63=(a08*a58);
  a61=(a61-a63);
  if (res[0]!=0) res[0][6]=a61;
  a63=(a52*a41);
  a64=(a20*a54);
  a65=(a52*a38);
  a64=(a64-a65);
  a65=(a64*a01);
  a63=(a63+a65);
  a65=(a20*a57);
  a63=(a63-a65);
  if (res[0]!=0) res[0][7]=a63;
  if (res[0]!=0) res[0][8]=a05;
  if (res[0]!=0) res[0][9]=a04;
  if (res[0]!=0) res[0][10]=a05;
  a65=(-a43);
  if (res[0]!=0) res[0][11]=a65;
  if (res[0]!=0) res[0][12]=a05;
  a66=arg[1]? arg[1][93] : 0;
  a03=(a66*a03);
  a67=arg[1]? arg[1][75] : 0;
  a09=(a67*a09);
  a68=arg[1]? arg[1][69] : 0;
  a69=(a68*a13);
  a70=arg[1]? arg[1][72] : 0;
  a71=(a70*a12);
  a69=(a69+a71);
  a16=(a69*a16);
  a09=(a09+a16);
  a70=(a70*a13);
  a68=(a68*a12);
  a70=(a70-a68);
  a11=(a70*a11);
  a09=(a09+a11);
  a11=arg[1]? arg[1][87] : 0;
  a09=(a09+a11);
  a00=(a09*a00);
  a19=(a67*a19);
  a21=(a21*a69);
  a19=(a19+a21);
  a22=(a22*a70);
  a19=(a19+a22);
  a23=(a19*a23);
  a25=(a67*a25);
  a27=(a27*a69);
  a25=(a25+a27);
  a28=(a28*a70);
  a25=(a25+a28);
  a28=(a25*a30);
  a32=(a67*a32);
  a34=(a34*a69);
  a32=(a32+a34);
  a35=(a35*a70);
  a32=(a32+a35);
  a35=(a32*a29);
  a28=(a28+a35);
  a36=(a28*a36);
  a23=(a23+a36);
  a32=(a32*a30);
  a25=(a25*a29);
  a32=(a32-a25);
  a26=(a32*a26);
  a23=(a23+a26);
  a37=(a67*a37);
  a39=(a69*a39);
  a37=(a37+a39);
  a40=(a70*a40);
  a37=(a37+a40);
  a37=(a37+a11);
  a23=(a23+a37);
  a40=(a23*a01);
  a39=(a00+a40);
  a26=(a03+a39);
  if (res[0]!=0) res[0][13]=a26;
  a25=(a08*a39);
  a17=(a67*a17);
  a29=(a08*a11);
  a17=(a17-a29);
  a29=(a02*a17);
  a25=(a25+a29);
  a29=(a67*a42);
  a25=(a25-a29);
  if (res[0]!=0) res[0][14]=a25;
  a29=(a20*a40);
  a38=(a19*a38);
  a30=(a20*a37);
  a38=(a38-a30);
  a30=(a38*a01);
  a29=(a29+a30);
  a30=(a19*a41);
  a29=(a29-a30);
  if (res[0]!=0) res[0][15]=a29;
  if (res[0]!=0) res[0][16]=a05;
  if (res[0]!=0) res[0][17]=a05;
  if (res[0]!=0) res[0][18]=a04;
  if (res[0]!=0) res[0][19]=a59;
  a04=(-a26);
  if (res[0]!=0) res[0][20]=a04;
  if (res[0]!=0) res[0][21]=a05;
  a30=(a67*a58);
  a11=(a46*a11);
  a48=(a67*a48);
  a11=(a11-a48);
  a02=(a02*a11);
  a30=(a30+a02);
  a02=(a46*a39);
  a30=(a30-a02);
  if (res[0]!=0) res[0][22]=a30;
  a02=(a19*a57);
  a37=(a52*a37);
  a54=(a19*a54);
  a37=(a37-a54);
  a01=(a37*a01);
  a02=(a02+a01);
  a01=(a52*a40);
  a02=(a02-a01);
  if (res[0]!=0) res[0][23]=a02;
  if (res[0]!=0) res[0][24]=a05;
  if (res[0]!=0) res[0][25]=a65;
  if (res[0]!=0) res[0][26]=a59;
  a59=arg[1]? arg[1][114] : 0;
  a65=arg[1]? arg[1][115] : 0;
  a65=(a65-a59);
  a01=(a32*a65);
  a54=(a01*a32);
  a54=(a59+a54);
  a48=(2.*a19);
  a36=5.0000000000000000e-01;
  a35=arg[1]? arg[1][116] : 0;
  a35=(a36*a35);
  a34=-5.0000000000000000e-01;
  a27=(a34*a59);
  a35=(a35+a27);
  a27=(a19*a35);
  a22=arg[1]? arg[1][118] : 0;
  a28=(a22*a28);
  a27=(a27+a28);
  a28=arg[1]? arg[1][119] : 0;
  a32=(a28*a32);
  a27=(a27+a32);
  a48=(a48*a27);
  a54=(a54+a48);
  a23=(a23*a40);
  a48=(a53*a57);
  a32=(a23+a48);
  a21=(a24*a41);
  a32=(a32+a21);
  a54=(a54+a32);
  a54=(a54-a23);
  a23=arg[1]? arg[1][108] : 0;
  a68=arg[1]? arg[1][109] : 0;
  a68=(a68-a23);
  a12=(a70*a68);
  a13=(a12*a70);
  a13=(a23+a13);
  a16=arg[1]? arg[1][112] : 0;
  a69=(a16*a69);
  a71=arg[1]? arg[1][113] : 0;
  a70=(a71*a70);
  a69=(a69+a70);
  a70=arg[1]? arg[1][110] : 0;
  a36=(a36*a70);
  a34=(a34*a23);
  a36=(a36+a34);
  a34=(a36*a67);
  a69=(a69+a34);
  a34=(2.*a69);
  a34=(a34*a67);
  a13=(a13+a34);
  a13=(a54+a13);
  a09=(a09*a00);
  a34=(a47*a51);
  a70=(a09+a34);
  a18=(a10*a18);
  a70=(a70+a18);
  a13=(a13+a70);
  a13=(a13-a09);
  a09=arg[1]? arg[1][102] : 0;
  a09=(a13+a09);
  a66=(a66*a03);
  a72=(a44*a45);
  a73=(a66+a72);
  a07=(a06*a07);
  a73=(a73+a07);
  a09=(a09+a73);
  a09=(a09-a66);
  if (res[0]!=0) res[0][27]=a09;
  a09=(a52*a35);
  a55=(a22*a55);
  a09=(a09+a55);
  a55=(a28*a56);
  a09=(a09+a55);
  a55=(a19*a09);
  a66=(a52*a27);
  a55=(a55+a66);
  a66=(a01*a56);
  a55=(a55+a66);
  a53=(a53*a40);
  a55=(a55-a53);
  a53=(a69*a46);
  a49=(a16*a49);
  a66=(a71*a50);
  a49=(a49+a66);
  a66=(a36*a46);
  a49=(a49+a66);
  a66=(a49*a67);
  a53=(a53+a66);
  a66=(a12*a50);
  a53=(a53+a66);
  a53=(a55+a53);
  a47=(a47*a00);
  a53=(a53-a47);
  a47=arg[1]? arg[1][105] : 0;
  a47=(a53+a47);
  a44=(a44*a03);
  a47=(a47-a44);
  if (res[0]!=0) res[0][28]=a47;
  a35=(a20*a35);
  a22=(a22*a31);
  a35=(a35+a22);
  a28=(a28*a33);
  a35=(a35+a28);
  a28=(a19*a35);
  a27=(a20*a27);
  a28=(a28+a27);
  a01=(a01*a33);
  a28=(a28+a01);
  a01=(a24*a40);
  a28=(a28-a01);
  a69=(a69*a08);
  a16=(a16*a14);
  a71=(a71*a15);
  a16=(a16+a71);
  a36=(a36*a08);
  a16=(a16+a36);
  a36=(a16*a67);
  a69=(a69+a36);
  a12=(a12*a15);
  a69=(a69+a12);
  a69=(a28+a69);
  a00=(a10*a00);
  a69=(a69-a00);
  a00=arg[1]? arg[1][106] : 0;
  a00=(a69+a00);
  a03=(a06*a03);
  a00=(a00-a03);
  if (res[0]!=0) res[0][29]=a00;
  a13=(a13*a67);
  a03=(a53*a46);
  a13=(a13+a03);
  a03=(a69*a08);
  a13=(a13+a03);
  a03=(a58*a11);
  a13=(a13+a03);
  a03=(a42*a17);
  a13=(a13-a03);
  if (res[0]!=0) res[0][30]=a13;
  a54=(a19*a54);
  a03=(a52*a55);
  a54=(a54+a03);
  a03=(a20*a28);
  a54=(a54+a03);
  a03=(a57*a37);
  a54=(a54+a03);
  a03=(a41*a38);
  a54=(a54-a03);
  if (res[0]!=0) res[0][31]=a54;
  if (res[0]!=0) res[0][32]=a43;
  if (res[0]!=0) res[0][33]=a05;
  if (res[0]!=0) res[0][34]=a04;
  if (res[0]!=0) res[0][35]=a47;
  a47=(a56*a65);
  a56=(a47*a56);
  a56=(a59+a56);
  a04=(2.*a52);
  a04=(a04*a09);
  a56=(a56+a04);
  a56=(a56+a32);
  a56=(a56-a48);
  a48=(a50*a68);
  a50=(a48*a50);
  a50=(a23+a50);
  a04=(2.*a49);
  a04=(a04*a46);
  a50=(a50+a04);
  a50=(a56+a50);
  a50=(a50+a70);
  a50=(a50-a34);
  a34=arg[1]? arg[1][103] : 0;
  a34=(a50+a34);
  a34=(a34+a73);
  a34=(a34-a72);
  if (res[0]!=0) res[0][36]=a34;
  a34=(a52*a35);
  a09=(a20*a09);
  a34=(a34+a09);
  a47=(a47*a33);
  a34=(a34+a47);
  a24=(a24*a57);
  a34=(a34-a24);
  a49=(a49*a08);
  a24=(a16*a46);
  a49=(a49+a24);
  a48=(a48*a15);
  a49=(a49+a48);
  a49=(a34+a49);
  a10=(a10*a51);
  a49=(a49-a10);
  a10=arg[1]? arg[1][107] : 0;
  a10=(a49+a10);
  a06=(a06*a45);
  a10=(a10-a06);
  if (res[0]!=0) res[0][37]=a10;
  a50=(a50*a46);
  a53=(a53*a67);
  a50=(a50+a53);
  a53=(a49*a08);
  a50=(a50+a53);
  a42=(a42*a62);
  a50=(a50+a42);
  a42=(a39*a11);
  a50=(a50-a42);
  if (res[0]!=0) res[0][38]=a50;
  a55=(a19*a55);
  a56=(a52*a56);
  a55=(a55+a56);
  a56=(a20*a34);
  a55=(a55+a56);
  a41=(a41*a64);
  a55=(a55+a41);
  a41=(a40*a37);
  a55=(a55-a41);
  if (res[0]!=0) res[0][39]=a55;
  if (res[0]!=0) res[0][40]=a60;
  if (res[0]!=0) res[0][41]=a26;
  if (res[0]!=0) res[0][42]=a05;
  if (res[0]!=0) res[0][43]=a00;
  if (res[0]!=0) res[0][44]=a10;
  a65=(a33*a65);
  a65=(a65*a33);
  a59=(a59+a65);
  a65=(2.*a20);
  a65=(a65*a35);
  a59=(a59+a65);
  a59=(a59+a32);
  a59=(a59-a21);
  a68=(a15*a68);
  a68=(a68*a15);
  a23=(a23+a68);
  a16=(2.*a16);
  a16=(a16*a08);
  a23=(a23+a16);
  a23=(a59+a23);
  a23=(a23+a70);
  a23=(a23-a18);
  a18=arg[1]? arg[1][104] : 0;
  a18=(a23+a18);
  a18=(a18+a73);
  a18=(a18-a07);
  if (res[0]!=0) res[0][45]=a18;
  a23=(a23*a08);
  a69=(a69*a67);
  a23=(a23+a69);
  a49=(a49*a46);
  a23=(a23+a49);
  a39=(a39*a17);
  a23=(a23+a39);
  a58=(a58*a62);
  a23=(a23-a58);
  if (res[0]!=0) res[0][46]=a23;
  a28=(a19*a28);
  a34=(a52*a34);
  a28=(a28+a34);
  a59=(a20*a59);
  a28=(a28+a59);
  a40=(a40*a38);
  a28=(a28+a40);
  a57=(a57*a64);
  a28=(a28-a57);
  if (res[0]!=0) res[0][47]=a28;
  if (res[0]!=0) res[0][48]=a61;
  if (res[0]!=0) res[0][49]=a25;
  if (res[0]!=0) res[0][50]=a30;
  if (res[0]!=0) res[0][51]=a13;
  if (res[0]!=0) res[0][52]=a50;
  if (res[0]!=0) res[0][53]=a23;
  a13=(a13*a67);
  a50=(a50*a46);
  a13=(a13+a50);
  a23=(a23*a08);
  a13=(a13+a23);
  a61=(a61*a62);
  a13=(a13+a61);
  a25=(a25*a17);
  a13=(a13+a25);
  a30=(a30*a11);
  a13=(a13+a30);
  if (res[0]!=0) res[0][54]=a13;
  a67=(a54*a67);
  a46=(a55*a46);
  a67=(a67+a46);
  a08=(a28*a08);
  a67=(a67+a08);
  a62=(a63*a62);
  a67=(a67+a62);
  a17=(a29*a17);
  a67=(a67+a17);
  a11=(a02*a11);
  a67=(a67+a11);
  if (res[0]!=0) res[0][55]=a67;
  if (res[0]!=0) res[0][56]=a63;
  if (res[0]!=0) res[0][57]=a29;
  if (res[0]!=0) res[0][58]=a02;
  if (res[0]!=0) res[0][59]=a54;
  if (res[0]!=0) res[0][60]=a55;
  if (res[0]!=0) res[0][61]=a28;
  if (res[0]!=0) res[0][62]=a67;
  a19=(a19*a54);
  a52=(a52*a55);
  a19=(a19+a52);
  a20=(a20*a28);
  a19=(a19+a20);
  a63=(a63*a64);
  a19=(a19+a63);
  a29=(a29*a38);
  a19=(a19+a29);
  a02=(a02*a37);
  a19=(a19+a02);
  if (res[0]!=0) res[0][63]=a19;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_mass_matrix(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_mass_matrix_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_mass_matrix_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_mass_matrix_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_mass_matrix_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_mass_matrix_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_mass_matrix_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_mass_matrix_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_mass_matrix_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_mass_matrix_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_mass_matrix_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_mass_matrix_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_mass_matrix_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_mass_matrix_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
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

#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 (four angles per instruction), chosen at load time */
__attribute__((target_clones("arch=x86-64-v3", "default")))
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

/* snakecg_sp2_mass_matrix_sincos: 580 CasADi instructions, printed one per line */
static void snakecg_sp2_mass_matrix_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58, w59;
  casadi_real w60, w61, w62, w63, w64, w65, w66, w67, w68, w69;
  casadi_real w70, w71, w72, w73;
  w0 = arg1[1];
  w1 = arg1[2];
  w2 = w0 + w1;
  w3 = arg1[0];
  w4 = w2 + w3;
  res0[0] = w4;
  w5 = 0.0;
  res0[1] = w5;
  res0[2] = w5;
  res0[3] = w5;
  w6 = arg1[95];
  w7 = w6 * w3;
  w8 = arg1[77];
  w9 = arg1[98];
  w10 = w8 * w9;
  w11 = arg1[71];
  w12 = arg2[0];
  w13 = w11 * w12;
  w14 = arg1[74];
  w15 = arg3[0];
  w16 = w14 * w15;
  w13 = w13 + w16;
  w16 = arg1[96];
  w17 = w13 * w16;
  w10 = w10 + w17;
  w14 = w14 * w12;
  w11 = w11 * w15;
  w14 = w14 - w11;
  w11 = arg1[97];
  w17 = w14 * w11;
  w10 = w10 + w17;
  w17 = arg1[89];
  w10 = w10 + w17;
  w18 = w10 * w0;
  w19 = arg1[86];
  w20 = w8 * w19;
  w21 = arg1[84];
  w22 = w21 * w13;
  w20 = w20 + w22;
  w22 = arg1[85];
  w23 = w22 * w14;
  w20 = w20 + w23;
  w23 = arg1[101];
  w24 = w20 * w23;
  w25 = arg1[80];
  w26 = w8 * w25;
  w27 = arg1[78];
  w28 = w27 * w13;
  w26 = w26 + w28;
  w28 = arg1[79];
  w29 = w28 * w14;
  w26 = w26 + w29;
  w29 = arg2[1];
  w30 = w26 * w29;
  w31 = arg1[83];
  w32 = w8 * w31;
  w33 = arg1[81];
  w34 = w33 * w13;
  w32 = w32 + w34;
  w34 = arg1[82];
  w35 = w34 * w14;
  w32 = w32 + w35;
  w35 = arg3[1];
  w36 = w32 * w35;
  w30 = w30 + w36;
  w36 = arg1[99];
  w37 = w30 * w36;
  w24 = w24 + w37;
  w32 = w32 * w29;
  w26 = w26 * w35;
  w32 = w32 - w26;
  w26 = arg1[100];
  w37 = w32 * w26;
  w24 = w24 + w37;
  w37 = arg1[92];
  w38 = w8 * w37;
  w39 = arg1[90];
  w40 = w13 * w39;
  w38 = w38 + w40;
  w40 = arg1[91];
  w41 = w14 * w40;
  w38 = w38 + w41;
  w38 = w38 + w17;
  w24 = w24 + w38;
  w41 = w24 * w1;
  w42 = w18 + w41;
  w43 = w7 + w42;
  res0[4] = w43;
  w44 = arg1[94];
  w45 = w44 * w3;
  w46 = arg1[76];
  w47 = w46 * w9;
  w48 = arg1[70];
  w49 = w48 * w12;
  w50 = arg1[73];
  w51 = w50 * w15;
  w49 = w49 + w51;
  w51 = w49 * w16;
  w47 = w47 + w51;
  w50 = w50 * w12;
  w48 = w48 * w15;
  w50 = w50 - w48;
  w48 = w50 * w11;
  w47 = w47 + w48;
  w48 = arg1[88];
  w47 = w47 + w48;
  w51 = w47 * w0;
  w52 = w46 * w19;
  w53 = w21 * w49;
  w52 = w52 + w53;
  w53 = w22 * w50;
  w52 = w52 + w53;
  w53 = w52 * w23;
  w54 = w46 * w25;
  w55 = w27 * w49;
  w54 = w54 + w55;
  w55 = w28 * w50;
  w54 = w54 + w55;
  w55 = w54 * w29;
  w56 = w46 * w31;
  w57 = w33 * w49;
  w56 = w56 + w57;
  w57 = w34 * w50;
  w56 = w56 + w57;
  w57 = w56 * w35;
  w55 = w55 + w57;
  w57 = w55 * w36;
  w53 = w53 + w57;
  w56 = w56 * w29;
  w54 = w54 * w35;
  w56 = w56 - w54;
  w54 = w56 * w26;
  w53 = w53 + w54;
  w54 = w46 * w37;
  w57 = w49 * w39;
  w54 = w54 + w57;
  w57 = w50 * w40;
  w54 = w54 + w57;
  w54 = w54 + w48;
  w53 = w53 + w54;
  w57 = w53 * w1;
  w58 = w51 + w57;
  w59 = w45 + w58;
  w60 = -w59;
  res0[5] = w60;
  w61 = w46 * w42;
  w62 = w8 * w48;
  w63 = w46 * w17;
  w62 = w62 - w63;
  w63 = w2 * w62;
  w61 = w61 + w63;
  w63 = w8 * w58;
  w61 = w61 - w63;
  res0[6] = w61;
  w63 = w52 * w41;
  w64 = w20 * w54;
  w65 = w52 * w38;
  w64 = w64 - w65;
  w65 = w64 * w1;
  w63 = w63 + w65;
  w65 = w20 * w57;
  w63 = w63 - w65;
  res0[7] = w63;
  res0[8] = w5;
  res0[9] = w4;
  res0[10] = w5;
  w65 = -w43;
  res0[11] = w65;
  res0[12] = w5;
  w66 = arg1[93];
  w3 = w66 * w3;
  w67 = arg1[75];
  w9 = w67 * w9;
  w68 = arg1[69];
  w69 = w68 * w12;
  w70 = arg1[72];
  w71 = w70 * w15;
  w69 = w69 + w71;
  w16 = w69 * w16;
  w9 = w9 + w16;
  w70 = w70 * w12;
  w68 = w68 * w15;
  w70 = w70 - w68;
  w11 = w70 * w11;
  w9 = w9 + w11;
  w11 = arg1[87];
  w9 = w9 + w11;
  w0 = w9 * w0;
  w19 = w67 * w19;
  w21 = w21 * w69;
  w19 = w19 + w21;
  w22 = w22 * w70;
  w19 = w19 + w22;
  w23 = w19 * w23;
  w25 = w67 * w25;
  w27 = w27 * w69;
  w25 = w25 + w27;
  w28 = w28 * w70;
  w25 = w25 + w28;
  w28 = w25 * w29;
  w31 = w67 * w31;
  w33 = w33 * w69;
  w31 = w31 + w33;
  w34 = w34 * w70;
  w31 = w31 + w34;
  w34 = w31 * w35;
  w28 = w28 + w34;
  w36 = w28 * w36;
  w23 = w23 + w36;
  w31 = w31 * w29;
  w25 = w25 * w35;
  w31 = w31 - w25;
  w26 = w31 * w26;
  w23 = w23 + w26;
  w37 = w67 * w37;
  w39 = w69 * w39;
  w37 = w37 + w39;
  w40 = w70 * w40;
  w37 = w37 + w40;
  w37 = w37 + w11;
  w23 = w23 + w37;
  w40 = w23 * w1;
  w39 = w0 + w40;
  w26 = w3 + w39;
  res0[13] = w26;
  w25 = w8 * w39;
  w17 = w67 * w17;
  w35 = w8 * w11;
  w17 = w17 - w35;
  w35 = w2 * w17;
  w25 = w25 + w35;
  w35 = w67 * w42;
  w25 = w25 - w35;
  res0[14] = w25;
  w35 = w20 * w40;
  w38 = w19 * w38;
  w29 = w20 * w37;
  w38 = w38 - w29;
  w29 = w38 * w1;
  w35 = w35 + w29;
  w29 = w19 * w41;
  w35 = w35 - w29;
  res0[15] = w35;
  res0[16] = w5;
  res0[17] = w5;
  res0[18] = w4;
  res0[19] = w59;
  w4 = -w26;
  res0[20] = w4;
  res0[21] = w5;
  w29 = w67 * w58;
  w11 = w46 * w11;
  w48 = w67 * w48;
  w11 = w11 - w48;
  w2 = w2 * w11;
  w29 = w29 + w2;
  w2 = w46 * w39;
  w29 = w29 - w2;
  res0[22] = w29;
  w2 = w19 * w57;
  w37 = w52 * w37;
  w54 = w19 * w54;
  w37 = w37 - w54;
  w1 = w37 * w1;
  w2 = w2 + w1;
  w1 = w52 * w40;
  w2 = w2 - w1;
  res0[23] = w2;
  res0[24] = w5;
  res0[25] = w65;
  res0[26] = w59;
  w59 = arg1[114];
  w65 = arg1[115];
  w65 = w65 - w59;
  w1 = w31 * w65;
  w54 = w1 * w31;
  w54 = w59 + w54;
  w48 = w19 + w19;
  w36 = 0.5;
  w34 = arg1[116];
  w34 = w36 * w34;
  w33 = (-0.5);
  w27 = w33 * w59;
  w34 = w34 + w27;
  w27 = w19 * w34;
  w22 = arg1[118];
  w28 = w22 * w28;
  w27 = w27 + w28;
  w28 = arg1[119];
  w31 = w28 * w31;
  w27 = w27 + w31;
  w48 = w48 * w27;
  w54 = w54 + w48;
  w23 = w23 * w40;
  w48 = w53 * w57;
  w31 = w23 + w48;
  w21 = w24 * w41;
  w31 = w31 + w21;
  w54 = w54 + w31;
  w54 = w54 - w23;
  w23 = arg1[108];
  w68 = arg1[109];
  w68 = w68 - w23;
  w15 = w70 * w68;
  w12 = w15 * w70;
  w12 = w23 + w12;
  w16 = arg1[112];
  w69 = w16 * w69;
  w71 = arg1[113];
  w70 = w71 * w70;
  w69 = w69 + w70;
  w70 = arg1[110];
  w36 = w36 * w70;
  w33 = w33 * w23;
  w36 = w36 + w33;
  w33 = w36 * w67;
  w69 = w69 + w33;
  w33 = w69 + w69;
  w33 = w33 * w67;
  w12 = w12 + w33;
  w12 = w54 + w12;
  w9 = w9 * w0;
  w33 = w47 * w51;
  w70 = w9 + w33;
  w18 = w10 * w18;
  w70 = w70 + w18;
  w12 = w12 + w70;
  w12 = w12 - w9;
  w9 = arg1[102];
  w9 = w12 + w9;
  w66 = w66 * w3;
  w72 = w44 * w45;
  w73 = w66 + w72;
  w7 = w6 * w7;
  w73 = w73 + w7;
  w9 = w9 + w73;
  w9 = w9 - w66;
  res0[27] = w9;
  w9 = w52 * w34;
  w55 = w22 * w55;
  w9 = w9 + w55;
  w55 = w28 * w56;
  w9 = w9 + w55;
  w55 = w19 * w9;
  w66 = w52 * w27;
  w55 = w55 + w66;
  w66 = w1 * w56;
  w55 = w55 + w66;
  w53 = w53 * w40;
  w55 = w55 - w53;
  w53 = w69 * w46;
  w49 = w16 * w49;
  w66 = w71 * w50;
  w49 = w49 + w66;
  w66 = w36 * w46;
  w49 = w49 + w66;
  w66 = w49 * w67;
  w53 = w53 + w66;
  w66 = w15 * w50;
  w53 = w53 + w66;
  w53 = w55 + w53;
  w47 = w47 * w0;
  w53 = w53 - w47;
  w47 = arg1[105];
  w47 = w53 + w47;
  w44 = w44 * w3;
  w47 = w47 - w44;
  res0[28] = w47;
  w34 = w20 * w34;
  w22 = w22 * w30;
  w34 = w34 + w22;
  w28 = w28 * w32;
  w34 = w34 + w28;
  w28 = w19 * w34;
  w27 = w20 * w27;
  w28 = w28 + w27;
  w1 = w1 * w32;
  w28 = w28 + w1;
  w1 = w24 * w40;
  w28 = w28 - w1;
  w69 = w69 * w8;
  w16 = w16 * w13;
  w71 = w71 * w14;
  w16 = w16 + w71;
  w36 = w36 * w8;
  w16 = w16 + w36;
  w36 = w16 * w67;
  w69 = w69 + w36;
  w15 = w15 * w14;
  w69 = w69 + w15;
  w69 = w28 + w69;
  w0 = w10 * w0;
  w69 = w69 - w0;
  w0 = arg1[106];
  w0 = w69 + w0;
  w3 = w6 * w3;
  w0 = w0 - w3;
  res0[29] = w0;
  w12 = w12 * w67;
  w3 = w53 * w46;
  w12 = w12 + w3;
  w3 = w69 * w8;
  w12 = w12 + w3;
  w3 = w58 * w11;
  w12 = w12 + w3;
  w3 = w42 * w17;
  w12 = w12 - w3;
  res0[30] = w12;
  w54 = w19 * w54;
  w3 = w52 * w55;
  w54 = w54 + w3;
  w3 = w20 * w28;
  w54 = w54 + w3;
  w3 = w57 * w37;
  w54 = w54 + w3;
  w3 = w41 * w38;
  w54 = w54 - w3;
  res0[31] = w54;
  res0[32] = w43;
  res0[33] = w5;
  res0[34] = w4;
  res0[35] = w47;
  w47 = w56 * w65;
  w56 = w47 * w56;
  w56 = w59 + w56;
  w4 = w52 + w52;
  w4 = w4 * w9;
  w56 = w56 + w4;
  w56 = w56 + w31;
  w56 = w56 - w48;
  w48 = w50 * w68;
  w50 = w48 * w50;
  w50 = w23 + w50;
  w4 = w49 + w49;
  w4 = w4 * w46;
  w50 = w50 + w4;
  w50 = w56 + w50;
  w50 = w50 + w70;
  w50 = w50 - w33;
  w33 = arg1[103];
  w33 = w50 + w33;
  w33 = w33 + w73;
  w33 = w33 - w72;
  res0[36] = w33;
  w33 = w52 * w34;
  w9 = w20 * w9;
  w33 = w33 + w9;
  w47 = w47 * w32;
  w33 = w33 + w47;
  w24 = w24 * w57;
  w33 = w33 - w24;
  w49 = w49 * w8;
  w24 = w16 * w46;
  w49 = w49 + w24;
  w48 = w48 * w14;
  w49 = w49 + w48;
  w49 = w33 + w49;
  w10 = w10 * w51;
  w49 = w49 - w10;
  w10 = arg1[107];
  w10 = w49 + w10;
  w6 = w6 * w45;
  w10 = w10 - w6;
  res0[37] = w10;
  w50 = w50 * w46;
  w53 = w53 * w67;
  w50 = w50 + w53;
  w53 = w49 * w8;
  w50 = w50 + w53;
  w42 = w42 * w62;
  w50 = w50 + w42;
  w42 = w39 * w11;
  w50 = w50 - w42;
  res0[38] = w50;
  w55 = w19 * w55;
  w56 = w52 * w56;
  w55 = w55 + w56;
  w56 = w20 * w33;
  w55 = w55 + w56;
  w41 = w41 * w64;
  w55 = w55 + w41;
  w41 = w40 * w37;
  w55 = w55 - w41;
  res0[39] = w55;
  res0[40] = w60;
  res0[41] = w26;
  res0[42] = w5;
  res0[43] = w0;
  res0[44] = w10;
  w65 = w32 * w65;
  w65 = w65 * w32;
  w59 = w59 + w65;
  w65 = w20 + w20;
  w65 = w65 * w34;
  w59 = w59 + w65;
  w59 = w59 + w31;
  w59 = w59 - w21;
  w68 = w14 * w68;
  w68 = w68 * w14;
  w23 = w23 + w68;
  w16 = w16 + w16;
  w16 = w16 * w8;
  w23 = w23 + w16;
  w23 = w59 + w23;
  w23 = w23 + w70;
  w23 = w23 - w18;
  w18 = arg1[104];
  w18 = w23 + w18;
  w18 = w18 + w73;
  w18 = w18 - w7;
  res0[45] = w18;
  w23 = w23 * w8;
  w69 = w69 * w67;
  w23 = w23 + w69;
  w49 = w49 * w46;
  w23 = w23 + w49;
  w39 = w39 * w17;
  w23 = w23 + w39;
  w58 = w58 * w62;
  w23 = w23 - w58;
  res0[46] = w23;
  w28 = w19 * w28;
  w33 = w52 * w33;
  w28 = w28 + w33;
  w59 = w20 * w59;
  w28 = w28 + w59;
  w40 = w40 * w38;
  w28 = w28 + w40;
  w57 = w57 * w64;
  w28 = w28 - w57;
  res0[47] = w28;
  res0[48] = w61;
  res0[49] = w25;
  res0[50] = w29;
  res0[51] = w12;
  res0[52] = w50;
  res0[53] = w23;
  w12 = w12 * w67;
  w50 = w50 * w46;
  w12 = w12 + w50;
  w23 = w23 * w8;
  w12 = w12 + w23;
  w61 = w61 * w62;
  w12 = w12 + w61;
  w25 = w25 * w17;
  w12 = w12 + w25;
  w29 = w29 * w11;
  w12 = w12 + w29;
  res0[54] = w12;
  w67 = w54 * w67;
  w46 = w55 * w46;
  w67 = w67 + w46;
  w8 = w28 * w8;
  w67 = w67 + w8;
  w62 = w63 * w62;
  w67 = w67 + w62;
  w17 = w35 * w17;
  w67 = w67 + w17;
  w11 = w2 * w11;
  w67 = w67 + w11;
  res0[55] = w67;
  res0[56] = w63;
  res0[57] = w35;
  res0[58] = w2;
  res0[59] = w54;
  res0[60] = w55;
  res0[61] = w28;
  res0[62] = w67;
  w19 = w19 * w54;
  w52 = w52 * w55;
  w19 = w19 + w52;
  w20 = w20 * w28;
  w19 = w19 + w20;
  w63 = w63 * w64;
  w19 = w19 + w63;
  w35 = w35 * w38;
  w19 = w19 + w35;
  w2 = w2 * w37;
  w19 = w19 + w2;
  res0[63] = w19;
}


CASADI_SYMBOL_EXPORT int snakecg_sp2_sample_batch_mass_matrix(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 75);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && res[0]) {
    /* cos and sin of q[7..8] of 16 samples at a time, then snakecg_sp2_mass_matrix_sincos
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
        snakecg_sp2_mass_matrix_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], ca + i * na, sa + i * na, res[0] + (i0 + i) * 64);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      r[0] = res[0] + i * 64;
      if (snakecg_sp2_mass_matrix(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}

/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Block driver rendered from derive/spatial/templates/block.c.j2.
 * snakecg_sp2_batch_mass_matrix evaluates 16 samples at a time with snakecg_sp2_mass_matrix_sincos_block (vectorized across
 * the samples): the inputs of a block are gathered sample-innermost, the cosines and sines of
 * the joint angles q[7..8] computed 16 at a time, and the outputs scattered back to
 * the batch layout. When an input or output is null or K varies per sample, the
 * per-sample driver snakecg_sp2_sample_batch_mass_matrix above answers instead. Same return codes.
 * ---------------------------------------------------------------------------------------- */

/* snakecg_sp2_mass_matrix_sincos over 16 samples: 552 CasADi instructions, one per line, in a loop the compiler vectorizes across the samples */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
/* a second copy for processors with AVX2 and FMA, chosen at load time */
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
static void snakecg_sp2_mass_matrix_sincos_block(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    casadi_real* restrict res0) {
  int s;
  for (s = 0; s < 16; ++s) {
    casadi_real w0 = arg1[1];
    casadi_real w1 = arg1[2];
    casadi_real w2 = w0 + w1;
    casadi_real w3 = arg1[0];
    casadi_real w4 = w2 + w3;
    res0[0 + s] = w4;
    casadi_real w5 = 0.0;
    res0[16 + s] = w5;
    res0[32 + s] = w4;
    res0[48 + s] = w5;
    res0[64 + s] = w5;
    res0[80 + s] = w4;
    res0[96 + s] = w5;
    w4 = arg1[95];
    casadi_real w6 = w4 * w3;
    casadi_real w7 = arg1[77];
    casadi_real w8 = arg1[98];
    casadi_real w9 = w7 * w8;
    casadi_real w10 = arg1[71];
    casadi_real w11 = arg2[0 + s];
    casadi_real w12 = w10 * w11;
    casadi_real w13 = arg1[74];
    casadi_real w14 = arg3[0 + s];
    casadi_real w15 = w13 * w14;
    w12 = w12 + w15;
    w15 = arg1[96];
    casadi_real w16 = w12 * w15;
    w9 = w9 + w16;
    w13 = w13 * w11;
    w10 = w10 * w14;
    w13 = w13 - w10;
    w10 = arg1[97];
    w16 = w13 * w10;
    w9 = w9 + w16;
    w16 = arg1[89];
    w9 = w9 + w16;
    casadi_real w17 = w9 * w0;
    casadi_real w18 = arg1[86];
    casadi_real w19 = w7 * w18;
    casadi_real w20 = arg1[84];
    casadi_real w21 = w20 * w12;
    w19 = w19 + w21;
    w21 = arg1[85];
    casadi_real w22 = w21 * w13;
    w19 = w19 + w22;
    w22 = arg1[101];
    casadi_real w23 = w19 * w22;
    casadi_real w24 = arg1[80];
    casadi_real w25 = w7 * w24;
    casadi_real w26 = arg1[78];
    casadi_real w27 = w26 * w12;
    w25 = w25 + w27;
    w27 = arg1[79];
    casadi_real w28 = w27 * w13;
    w25 = w25 + w28;
    w28 = arg2[16 + s];
    casadi_real w29 = w25 * w28;
    casadi_real w30 = arg1[83];
    casadi_real w31 = w7 * w30;
    casadi_real w32 = arg1[81];
    casadi_real w33 = w32 * w12;
    w31 = w31 + w33;
    w33 = arg1[82];
    casadi_real w34 = w33 * w13;
    w31 = w31 + w34;
    w34 = arg3[16 + s];
    casadi_real w35 = w31 * w34;
    w29 = w29 + w35;
    w35 = arg1[99];
    casadi_real w36 = w29 * w35;
    w23 = w23 + w36;
    w31 = w31 * w28;
    w25 = w25 * w34;
    w31 = w31 - w25;
    w25 = arg1[100];
    w36 = w31 * w25;
    w23 = w23 + w36;
    w36 = arg1[92];
    casadi_real w37 = w7 * w36;
    casadi_real w38 = arg1[90];
    casadi_real w39 = w12 * w38;
    w37 = w37 + w39;
    w39 = arg1[91];
    casadi_real w40 = w13 * w39;
    w37 = w37 + w40;
    w37 = w37 + w16;
    w23 = w23 + w37;
    w40 = w23 * w1;
    casadi_real w41 = w17 + w40;
    casadi_real w42 = w6 + w41;
    casadi_real w43 = -w42;
    res0[112 + s] = w43;
    w43 = arg1[94];
    casadi_real w44 = w43 * w3;
    casadi_real w45 = arg1[76];
    casadi_real w46 = w45 * w8;
    casadi_real w47 = arg1[70];
    casadi_real w48 = w47 * w11;
    casadi_real w49 = arg1[73];
    casadi_real w50 = w49 * w14;
    w48 = w48 + w50;
    w50 = w48 * w15;
    w46 = w46 + w50;
    w49 = w49 * w11;
    w47 = w47 * w14;
    w49 = w49 - w47;
    w47 = w49 * w10;
    w46 = w46 + w47;
    w47 = arg1[88];
    w46 = w46 + w47;
    w50 = w46 * w0;
    casadi_real w51 = w45 * w18;
    casadi_real w52 = w20 * w48;
    w51 = w51 + w52;
    w52 = w21 * w49;
    w51 = w51 + w52;
    w52 = w51 * w22;
    casadi_real w53 = w45 * w24;
    casadi_real w54 = w26 * w48;
    w53 = w53 + w54;
    w54 = w27 * w49;
    w53 = w53 + w54;
    w54 = w53 * w28;
    casadi_real w55 = w45 * w30;
    casadi_real w56 = w32 * w48;
    w55 = w55 + w56;
    w56 = w33 * w49;
    w55 = w55 + w56;
    w56 = w55 * w34;
    w54 = w54 + w56;
    w56 = w54 * w35;
    w52 = w52 + w56;
    w55 = w55 * w28;
    w53 = w53 * w34;
    w55 = w55 - w53;
    w53 = w55 * w25;
    w52 = w52 + w53;
    w53 = w45 * w36;
    w56 = w48 * w38;
    w53 = w53 + w56;
    w56 = w49 * w39;
    w53 = w53 + w56;
    w53 = w53 + w47;
    w52 = w52 + w53;
    w56 = w52 * w1;
    casadi_real w57 = w50 + w56;
    casadi_real w58 = w44 + w57;
    res0[128 + s] = w58;
    casadi_real w59 = arg1[114];
    casadi_real w60 = arg1[75];
    w30 = w60 * w30;
    casadi_real w61 = arg1[69];
    casadi_real w62 = w61 * w11;
    casadi_real w63 = arg1[72];
    casadi_real w64 = w63 * w14;
    w62 = w62 + w64;
    w32 = w32 * w62;
    w30 = w30 + w32;
    w63 = w63 * w11;
    w61 = w61 * w14;
    w63 = w63 - w61;
    w33 = w33 * w63;
    w30 = w30 + w33;
    w33 = w30 * w28;
    w24 = w60 * w24;
    w26 = w26 * w62;
    w24 = w24 + w26;
    w27 = w27 * w63;
    w24 = w24 + w27;
    w27 = w24 * w34;
    w33 = w33 - w27;
    w27 = arg1[115];
    w27 = w27 - w59;
    w26 = w33 * w27;
    w61 = w26 * w33;
    w61 = w59 + w61;
    w18 = w60 * w18;
    w20 = w20 * w62;
    w18 = w18 + w20;
    w21 = w21 * w63;
    w18 = w18 + w21;
    w21 = w18 + w18;
    w20 = 0.5;
    w14 = arg1[116];
    w14 = w20 * w14;
    w11 = (-0.5);
    w32 = w11 * w59;
    w14 = w14 + w32;
    w32 = w18 * w14;
    w64 = arg1[118];
    w24 = w24 * w28;
    w30 = w30 * w34;
    w24 = w24 + w30;
    w30 = w64 * w24;
    w32 = w32 + w30;
    w30 = arg1[119];
    w34 = w30 * w33;
    w32 = w32 + w34;
    w21 = w21 * w32;
    w61 = w61 + w21;
    w22 = w18 * w22;
    w24 = w24 * w35;
    w22 = w22 + w24;
    w33 = w33 * w25;
    w22 = w22 + w33;
    w36 = w60 * w36;
    w38 = w62 * w38;
    w36 = w36 + w38;
    w39 = w63 * w39;
    w36 = w36 + w39;
    w39 = arg1[87];
    w36 = w36 + w39;
    w22 = w22 + w36;
    w38 = w22 * w1;
    w22 = w22 * w38;
    w33 = w52 * w56;
    w25 = w22 + w33;
    w24 = w23 * w40;
    w25 = w25 + w24;
    w61 = w61 + w25;
    w61 = w61 - w22;
    w22 = arg1[108];
    w35 = arg1[109];
    w35 = w35 - w22;
    w21 = w63 * w35;
    w34 = w21 * w63;
    w34 = w22 + w34;
    w28 = arg1[112];
    casadi_real w65 = w28 * w62;
    casadi_real w66 = arg1[113];
    casadi_real w67 = w66 * w63;
    w65 = w65 + w67;
    w67 = arg1[110];
    w20 = w20 * w67;
    w11 = w11 * w22;
    w20 = w20 + w11;
    w11 = w20 * w60;
    w65 = w65 + w11;
    w11 = w65 + w65;
    w11 = w11 * w60;
    w34 = w34 + w11;
    w34 = w61 + w34;
    w8 = w60 * w8;
    w62 = w62 * w15;
    w8 = w8 + w62;
    w63 = w63 * w10;
    w8 = w8 + w63;
    w8 = w8 + w39;
    w0 = w8 * w0;
    w8 = w8 * w0;
    w63 = w46 * w50;
    w10 = w8 + w63;
    w17 = w9 * w17;
    w10 = w10 + w17;
    w34 = w34 + w10;
    w34 = w34 - w8;
    w8 = arg1[102];
    w8 = w34 + w8;
    w62 = arg1[93];
    w3 = w62 * w3;
    w62 = w62 * w3;
    w15 = w43 * w44;
    w11 = w62 + w15;
    w6 = w4 * w6;
    w11 = w11 + w6;
    w8 = w8 + w11;
    w8 = w8 - w62;
    res0[144 + s] = w8;
    res0[160 + s] = w42;
    res0[176 + s] = w5;
    w42 = w0 + w38;
    w8 = w3 + w42;
    w62 = -w8;
    res0[192 + s] = w62;
    w62 = w51 * w14;
    w54 = w64 * w54;
    w62 = w62 + w54;
    w54 = w30 * w55;
    w62 = w62 + w54;
    w54 = w18 * w62;
    w67 = w51 * w32;
    w54 = w54 + w67;
    w67 = w26 * w55;
    w54 = w54 + w67;
    w52 = w52 * w38;
    w54 = w54 - w52;
    w52 = w65 * w45;
    w48 = w28 * w48;
    w67 = w66 * w49;
    w48 = w48 + w67;
    w67 = w20 * w45;
    w48 = w48 + w67;
    w67 = w48 * w60;
    w52 = w52 + w67;
    w67 = w21 * w49;
    w52 = w52 + w67;
    w52 = w54 + w52;
    w46 = w46 * w0;
    w52 = w52 - w46;
    w46 = arg1[105];
    w46 = w52 + w46;
    w43 = w43 * w3;
    w46 = w46 - w43;
    res0[208 + s] = w46;
    w46 = w55 * w27;
    w55 = w46 * w55;
    w55 = w59 + w55;
    w43 = w51 + w51;
    w43 = w43 * w62;
    w55 = w55 + w43;
    w55 = w55 + w25;
    w55 = w55 - w33;
    w33 = w49 * w35;
    w49 = w33 * w49;
    w49 = w22 + w49;
    w43 = w48 + w48;
    w43 = w43 * w45;
    w49 = w49 + w43;
    w49 = w55 + w49;
    w49 = w49 + w10;
    w49 = w49 - w63;
    w63 = arg1[103];
    w63 = w49 + w63;
    w63 = w63 + w11;
    w63 = w63 - w15;
    res0[224 + s] = w63;
    w58 = -w58;
    res0[240 + s] = w58;
    res0[256 + s] = w8;
    res0[272 + s] = w5;
    w14 = w19 * w14;
    w64 = w64 * w29;
    w14 = w14 + w64;
    w30 = w30 * w31;
    w14 = w14 + w30;
    w30 = w18 * w14;
    w32 = w19 * w32;
    w30 = w30 + w32;
    w26 = w26 * w31;
    w30 = w30 + w26;
    w26 = w23 * w38;
    w30 = w30 - w26;
    w65 = w65 * w7;
    w28 = w28 * w12;
    w66 = w66 * w13;
    w28 = w28 + w66;
    w20 = w20 * w7;
    w28 = w28 + w20;
    w20 = w28 * w60;
    w65 = w65 + w20;
    w21 = w21 * w13;
    w65 = w65 + w21;
    w65 = w30 + w65;
    w0 = w9 * w0;
    w65 = w65 - w0;
    w0 = arg1[106];
    w0 = w65 + w0;
    w3 = w4 * w3;
    w0 = w0 - w3;
    res0[288 + s] = w0;
    w0 = w51 * w14;
    w62 = w19 * w62;
    w0 = w0 + w62;
    w46 = w46 * w31;
    w0 = w0 + w46;
    w23 = w23 * w56;
    w0 = w0 - w23;
    w48 = w48 * w7;
    w23 = w28 * w45;
    w48 = w48 + w23;
    w33 = w33 * w13;
    w48 = w48 + w33;
    w48 = w0 + w48;
    w9 = w9 * w50;
    w48 = w48 - w9;
    w9 = arg1[107];
    w9 = w48 + w9;
    w4 = w4 * w44;
    w9 = w9 - w4;
    res0[304 + s] = w9;
    w27 = w31 * w27;
    w27 = w27 * w31;
    w59 = w59 + w27;
    w27 = w19 + w19;
    w27 = w27 * w14;
    w59 = w59 + w27;
    w59 = w59 + w25;
    w59 = w59 - w24;
    w35 = w13 * w35;
    w35 = w35 * w13;
    w22 = w22 + w35;
    w28 = w28 + w28;
    w28 = w28 * w7;
    w22 = w22 + w28;
    w22 = w59 + w22;
    w22 = w22 + w10;
    w22 = w22 - w17;
    w17 = arg1[104];
    w17 = w22 + w17;
    w17 = w17 + w11;
    w17 = w17 - w6;
    res0[320 + s] = w17;
    w17 = w45 * w41;
    w6 = w7 * w47;
    w11 = w45 * w16;
    w6 = w6 - w11;
    w11 = w2 * w6;
    w17 = w17 + w11;
    w11 = w7 * w57;
    w17 = w17 - w11;
    res0[336 + s] = w17;
    w11 = w7 * w42;
    w16 = w60 * w16;
    w10 = w7 * w39;
    w16 = w16 - w10;
    w10 = w2 * w16;
    w11 = w11 + w10;
    w10 = w60 * w41;
    w11 = w11 - w10;
    res0[352 + s] = w11;
    w10 = w60 * w57;
    w39 = w45 * w39;
    w47 = w60 * w47;
    w39 = w39 - w47;
    w2 = w2 * w39;
    w10 = w10 + w2;
    w2 = w45 * w42;
    w10 = w10 - w2;
    res0[368 + s] = w10;
    w34 = w34 * w60;
    w2 = w52 * w45;
    w34 = w34 + w2;
    w2 = w65 * w7;
    w34 = w34 + w2;
    w2 = w57 * w39;
    w34 = w34 + w2;
    w2 = w41 * w16;
    w34 = w34 - w2;
    res0[384 + s] = w34;
    w49 = w49 * w45;
    w52 = w52 * w60;
    w49 = w49 + w52;
    w52 = w48 * w7;
    w49 = w49 + w52;
    w41 = w41 * w6;
    w49 = w49 + w41;
    w41 = w42 * w39;
    w49 = w49 - w41;
    res0[400 + s] = w49;
    w22 = w22 * w7;
    w65 = w65 * w60;
    w22 = w22 + w65;
    w48 = w48 * w45;
    w22 = w22 + w48;
    w42 = w42 * w16;
    w22 = w22 + w42;
    w57 = w57 * w6;
    w22 = w22 - w57;
    res0[416 + s] = w22;
    w34 = w34 * w60;
    w49 = w49 * w45;
    w34 = w34 + w49;
    w22 = w22 * w7;
    w34 = w34 + w22;
    w17 = w17 * w6;
    w34 = w34 + w17;
    w11 = w11 * w16;
    w34 = w34 + w11;
    w10 = w10 * w39;
    w34 = w34 + w10;
    res0[432 + s] = w34;
    w34 = w51 * w40;
    w10 = w19 * w53;
    w11 = w51 * w37;
    w10 = w10 - w11;
    w11 = w10 * w1;
    w34 = w34 + w11;
    w11 = w19 * w56;
    w34 = w34 - w11;
    res0[448 + s] = w34;
    w11 = w19 * w38;
    w37 = w18 * w37;
    w17 = w19 * w36;
    w37 = w37 - w17;
    w17 = w37 * w1;
    w11 = w11 + w17;
    w17 = w18 * w40;
    w11 = w11 - w17;
    res0[464 + s] = w11;
    w17 = w18 * w56;
    w36 = w51 * w36;
    w53 = w18 * w53;
    w36 = w36 - w53;
    w1 = w36 * w1;
    w17 = w17 + w1;
    w1 = w51 * w38;
    w17 = w17 - w1;
    res0[480 + s] = w17;
    w61 = w18 * w61;
    w1 = w51 * w54;
    w61 = w61 + w1;
    w1 = w19 * w30;
    w61 = w61 + w1;
    w1 = w56 * w36;
    w61 = w61 + w1;
    w1 = w40 * w37;
    w61 = w61 - w1;
    res0[496 + s] = w61;
    w54 = w18 * w54;
    w55 = w51 * w55;
    w54 = w54 + w55;
    w55 = w19 * w0;
    w54 = w54 + w55;
    w40 = w40 * w10;
    w54 = w54 + w40;
    w40 = w38 * w36;
    w54 = w54 - w40;
    res0[512 + s] = w54;
    w30 = w18 * w30;
    w0 = w51 * w0;
    w30 = w30 + w0;
    w59 = w19 * w59;
    w30 = w30 + w59;
    w38 = w38 * w37;
    w30 = w30 + w38;
    w56 = w56 * w10;
    w30 = w30 - w56;
    res0[528 + s] = w30;
    w60 = w61 * w60;
    w45 = w54 * w45;
    w60 = w60 + w45;
    w7 = w30 * w7;
    w60 = w60 + w7;
    w6 = w34 * w6;
    w60 = w60 + w6;
    w16 = w11 * w16;
    w60 = w60 + w16;
    w39 = w17 * w39;
    w60 = w60 + w39;
    res0[544 + s] = w60;
    w18 = w18 * w61;
    w51 = w51 * w54;
    w18 = w18 + w51;
    w19 = w19 * w30;
    w18 = w18 + w19;
    w34 = w34 * w10;
    w18 = w18 + w34;
    w11 = w11 * w37;
    w18 = w18 + w11;
    w17 = w17 * w36;
    w18 = w18 + w17;
    res0[560 + s] = w18;
  }
}

static const short snakecg_sp2_mass_matrix_sincos_block_entry[64] = {
    0, 1, 3, 6, 10, 15, 21, 28, 1, 2, 4, 7, 11, 16, 22, 29,
    3, 4, 5, 8, 12, 17, 23, 30, 6, 7, 8, 9, 13, 18, 24, 31,
    10, 11, 12, 13, 14, 19, 25, 32, 15, 16, 17, 18, 19, 20, 26, 33,
    21, 22, 23, 24, 25, 26, 27, 34, 28, 29, 30, 31, 32, 33, 34, 35
};
/* The scatter of one output of a block to the batch layout: entry e of sample i, at
 * x[src[e] * 16 + i] in the block (src null: at x[e * 16 + i]), to y[i * nnz + e], m samples.
 * A full block goes 4 entries by 4 samples at a time, transposed in vector registers and
 * stored 4 entries at once (an AVX2 copy chosen at load time), the rest one by one. */
#include <string.h>
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) \
    && defined(__linux__)
typedef casadi_real snakecg_sp2_mass_matrix_sincos_block_v4 __attribute__((vector_size(32)));
typedef long long snakecg_sp2_mass_matrix_sincos_block_i4 __attribute__((vector_size(32)));
__attribute__((target_clones("arch=x86-64-v3", "default")))
static void snakecg_sp2_mass_matrix_sincos_block_scatter(const casadi_real* x, const short* src, casadi_int nnz,
    casadi_real* y, casadi_int m) {
  casadi_int e = 0, i;
  const snakecg_sp2_mass_matrix_sincos_block_i4 lo = {0, 4, 2, 6}, hi = {1, 5, 3, 7};
  const snakecg_sp2_mass_matrix_sincos_block_i4 first = {0, 1, 4, 5}, second = {2, 3, 6, 7};
  if (m == 16) {
    for (; e + 4 <= nnz; e += 4) {
      const casadi_real* x0 = x + (src ? src[e] : e) * 16;
      const casadi_real* x1 = x + (src ? src[e + 1] : e + 1) * 16;
      const casadi_real* x2 = x + (src ? src[e + 2] : e + 2) * 16;
      const casadi_real* x3 = x + (src ? src[e + 3] : e + 3) * 16;
      for (i = 0; i < 16; i += 4) {
        snakecg_sp2_mass_matrix_sincos_block_v4 a, b, c, d, t0, t1, t2, t3, r;
        memcpy(&a, x0 + i, sizeof a);
        memcpy(&b, x1 + i, sizeof b);
        memcpy(&c, x2 + i, sizeof c);
        memcpy(&d, x3 + i, sizeof d);
        t0 = __builtin_shuffle(a, b, lo); /* (a0 b0 a2 b2) */
        t1 = __builtin_shuffle(a, b, hi); /* (a1 b1 a3 b3) */
        t2 = __builtin_shuffle(c, d, lo);
        t3 = __builtin_shuffle(c, d, hi);
        r = __builtin_shuffle(t0, t2, first); /* sample i: (a0 b0 c0 d0) */
        memcpy(y + i * nnz + e, &r, sizeof r);
        r = __builtin_shuffle(t1, t3, first);
        memcpy(y + (i + 1) * nnz + e, &r, sizeof r);
        r = __builtin_shuffle(t0, t2, second);
        memcpy(y + (i + 2) * nnz + e, &r, sizeof r);
        r = __builtin_shuffle(t1, t3, second);
        memcpy(y + (i + 3) * nnz + e, &r, sizeof r);
      }
    }
  }
  for (; e < nnz; ++e) {
    const casadi_real* x0 = x + (src ? src[e] : e) * 16;
    for (i = 0; i < m; ++i) y[i * nnz + e] = x0[i];
  }
}
#else
static void snakecg_sp2_mass_matrix_sincos_block_scatter(const casadi_real* x, const short* src, casadi_int nnz,
    casadi_real* y, casadi_int m) {
  casadi_int e, i;
  for (e = 0; e < nnz; ++e) {
    const casadi_real* x0 = x + (src ? src[e] : e) * 16;
    for (i = 0; i < m; ++i) y[i * nnz + e] = x0[i];
  }
}
#endif

CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_mass_matrix(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  casadi_real *work, *cq, *sq;
  casadi_real* in0;
  casadi_real* out0;
  casadi_int i, i0, m, e, src;
  int large;
  if (!(arg[0] && arg[1] && res[0] && stride[1] == 0)) {
    return snakecg_sp2_sample_batch_mass_matrix(n, arg, stride, res);
  }
  work = (casadi_real*) malloc(sizeof(casadi_real) * 784);
  if (!work) return -1;
  cq = work;
  sq = cq + 32;
  in0 = sq + 32;
  out0 = in0 + 144;
  for (i0 = 0; i0 < n; i0 += 16) {
    m = n - i0 < 16 ? n - i0 : 16;
    /* gather the entries the kernel and the sines and cosines read (the last sample repeated
     * into the unused slots of a partial block) */
    for (i = 0; i < 16; ++i) {
      src = i0 + (i < m ? i : m - 1);
      for (e = 7; e < 9; ++e) in0[e * 16 + i] = arg[0][src * stride[0] + e];
    }
    for (e = 0; e < 2; ++e) {
      const casadi_real* x = in0 + (7 + e) * 16;
      large = 0;
      for (i = 0; i < 16; ++i) large |= !(fabs(x[i]) <= SNAKECG_SINCOS_MAX);
      snakecg_sincos_block(x, cq + e * 16, sq + e * 16);
      if (large) snakecg_sincos_large(x, cq + e * 16, sq + e * 16, 16);
    }
    snakecg_sp2_mass_matrix_sincos_block(in0, arg[1], cq, sq, out0);
    /* scatter: the block's outputs to the batch layout; the kernel gives the
     * upper triangle of the symmetric output M, the table snakecg_sp2_mass_matrix_sincos_block_entry maps
     * each entry to its place in the triangle */
    snakecg_sp2_mass_matrix_sincos_block_scatter(out0, snakecg_sp2_mass_matrix_sincos_block_entry, 64, res[0] + i0 * 64, m);
  }
  free(work);
  return 0;
}
