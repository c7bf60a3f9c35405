/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_row() of
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
  #define CASADI_PREFIX(ID) snakecg_sp2_contact_row_ ## ID
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
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_s5 CASADI_PREFIX(s5)
#define casadi_s6 CASADI_PREFIX(s6)
#define casadi_s7 CASADI_PREFIX(s7)
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
CASADI_SYMBOL_EXPORT void snakecg_sp2_contact_row_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_contact_row_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_contact_row_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {8, 1, 1};
static const casadi_int casadi_s2[3] = {120, 1, 1};
static const casadi_int casadi_s3[3] = {3, 1, 1};
static const casadi_int casadi_s4[3] = {6, 1, 1};
static const casadi_int casadi_s5[3] = {1, 8, 1};
static const casadi_int casadi_s6[3] = {1, 6, 1};
static const casadi_int casadi_s7[3] = {1, 1, 1};

/* snakecg_sp2_contact_row:(q[9],v[8],K[120],link[3],point[3],normal[3],rho[3],v_obj[6])->(a_snake[1x8],g_obj[1x6],adot_v,position[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70;
  a00=1.;
  a01=-2.;
  a02=arg[0]? arg[0][4] : 0;
  a03=casadi_sq(a02);
  a03=(a01*a03);
  a04=(a00+a03);
  a05=arg[0]? arg[0][5] : 0;
  a06=casadi_sq(a05);
  a06=(a01*a06);
  a04=(a04+a06);
  a07=arg[5]? arg[5][0] : 0;
  a08=(a04*a07);
  a09=arg[0]? arg[0][6] : 0;
  a10=(2.*a09);
  a11=(a10*a05);
  a12=arg[0]? arg[0][3] : 0;
  a13=(2.*a12);
  a14=(a13*a02);
  a11=(a11+a14);
  a15=arg[5]? arg[5][1] : 0;
  a16=(a11*a15);
  a08=(a08+a16);
  a09=(a01*a09);
  a16=(a09*a02);
  a13=(a13*a05);
  a16=(a16+a13);
  a17=arg[5]? arg[5][2] : 0;
  a18=(a16*a17);
  a08=(a08+a18);
  a08=(-a08);
  if (res[0]!=0) res[0][0]=a08;
  a08=(a09*a05);
  a08=(a08+a14);
  a14=(a08*a07);
  a18=casadi_sq(a12);
  a01=(a01*a18);
  a00=(a00+a01);
  a06=(a00+a06);
  a01=(a06*a15);
  a14=(a14+a01);
  a01=(a10*a12);
  a18=(2.*a02);
  a18=(a18*a05);
  a01=(a01+a18);
  a05=(a01*a17);
  a14=(a14+a05);
  a14=(-a14);
  if (res[0]!=0) res[0][1]=a14;
  a10=(a10*a02);
  a10=(a10+a13);
  a13=(a10*a07);
  a09=(a09*a12);
  a09=(a09+a18);
  a18=(a09*a15);
  a13=(a13+a18);
  a00=(a00+a03);
  a03=(a00*a17);
  a13=(a13+a03);
  a13=(-a13);
  if (res[0]!=0) res[0][2]=a13;
  a13=arg[2]? arg[2][69] : 0;
  a03=(a13*a16);
  a18=arg[2]? arg[2][70] : 0;
  a12=(a18*a01);
  a03=(a03+a12);
  a12=arg[2]? arg[2][71] : 0;
  a02=(a12*a00);
  a03=(a03+a02);
  a02=arg[0]? arg[0][7] : 0;
  a14=cos(a02);
  a05=(a03*a14);
  a19=arg[2]? arg[2][72] : 0;
  a20=(a19*a16);
  a21=arg[2]? arg[2][73] : 0;
  a22=(a21*a01);
  a20=(a20+a22);
  a22=arg[2]? arg[2][74] : 0;
  a23=(a22*a00);
  a20=(a20+a23);
  a02=sin(a02);
  a23=(a20*a02);
  a05=(a05+a23);
  a23=arg[3]? arg[3][1] : 0;
  a24=(a05*a23);
  a25=arg[2]? arg[2][75] : 0;
  a26=(a25*a16);
  a27=arg[2]? arg[2][76] : 0;
  a28=(a27*a01);
  a26=(a26+a28);
  a28=arg[2]? arg[2][77] : 0;
  a29=(a28*a00);
  a26=(a26+a29);
  a29=arg[2]? arg[2][80] : 0;
  a30=(a26*a29);
  a31=arg[2]? arg[2][78] : 0;
  a32=(a31*a05);
  a30=(a30+a32);
  a32=arg[2]? arg[2][79] : 0;
  a20=(a20*a14);
  a03=(a03*a02);
  a20=(a20-a03);
  a03=(a32*a20);
  a30=(a30+a03);
  a03=arg[0]? arg[0][8] : 0;
  a33=cos(a03);
  a34=(a30*a33);
  a35=arg[2]? arg[2][83] : 0;
  a36=(a26*a35);
  a37=arg[2]? arg[2][81] : 0;
  a38=(a37*a05);
  a36=(a36+a38);
  a38=arg[2]? arg[2][82] : 0;
  a39=(a38*a20);
  a36=(a36+a39);
  a03=sin(a03);
  a39=(a36*a03);
  a34=(a34+a39);
  a39=arg[3]? arg[3][2] : 0;
  a34=(a34*a39);
  a24=(a24+a34);
  a34=arg[3]? arg[3][0] : 0;
  a40=(a16*a34);
  a24=(a24+a40);
  a40=arg[2]? arg[2][51] : 0;
  a40=(a40*a23);
  a40=(a34+a40);
  a41=arg[2]? arg[2][60] : 0;
  a41=(a41*a39);
  a40=(a40+a41);
  a41=arg[4]? arg[4][0] : 0;
  a40=(a40*a41);
  a42=arg[2]? arg[2][52] : 0;
  a42=(a42*a23);
  a43=arg[2]? arg[2][61] : 0;
  a43=(a43*a39);
  a42=(a42+a43);
  a43=arg[4]? arg[4][1] : 0;
  a42=(a42*a43);
  a40=(a40+a42);
  a42=arg[2]? arg[2][53] : 0;
  a42=(a42*a23);
  a44=arg[2]? arg[2][62] : 0;
  a44=(a44*a39);
  a42=(a42+a44);
  a44=arg[4]? arg[4][2] : 0;
  a42=(a42*a44);
  a40=(a40+a42);
  a24=(a24*a40);
  a42=(a20*a23);
  a36=(a36*a33);
  a30=(a30*a03);
  a36=(a36-a30);
  a36=(a36*a39);
  a42=(a42+a36);
  a36=(a01*a34);
  a42=(a42+a36);
  a36=arg[2]? arg[2][54] : 0;
  a36=(a36*a23);
  a30=arg[2]? arg[2][63] : 0;
  a30=(a30*a39);
  a36=(a36+a30);
  a36=(a36*a41);
  a30=arg[2]? arg[2][55] : 0;
  a30=(a30*a23);
  a30=(a34+a30);
  a45=arg[2]? arg[2][64] : 0;
  a45=(a45*a39);
  a30=(a30+a45);
  a30=(a30*a43);
  a36=(a36+a30);
  a30=arg[2]? arg[2][56] : 0;
  a30=(a30*a23);
  a45=arg[2]? arg[2][65] : 0;
  a45=(a45*a39);
  a30=(a30+a45);
  a30=(a30*a44);
  a36=(a36+a30);
  a42=(a42*a36);
  a24=(a24+a42);
  a42=(a26*a23);
  a30=arg[2]? arg[2][86] : 0;
  a45=(a26*a30);
  a46=arg[2]? arg[2][84] : 0;
  a47=(a46*a05);
  a45=(a45+a47);
  a47=arg[2]? arg[2][85] : 0;
  a48=(a47*a20);
  a45=(a45+a48);
  a48=(a45*a39);
  a42=(a42+a48);
  a48=(a00*a34);
  a42=(a42+a48);
  a48=arg[2]? arg[2][57] : 0;
  a48=(a48*a23);
  a49=arg[2]? arg[2][66] : 0;
  a49=(a49*a39);
  a48=(a48+a49);
  a48=(a48*a41);
  a41=arg[2]? arg[2][58] : 0;
  a41=(a41*a23);
  a49=arg[2]? arg[2][67] : 0;
  a49=(a49*a39);
  a41=(a41+a49);
  a41=(a41*a43);
  a48=(a48+a41);
  a41=arg[2]? arg[2][59] : 0;
  a41=(a41*a23);
  a41=(a34+a41);
  a43=arg[2]? arg[2][68] : 0;
  a43=(a43*a39);
  a41=(a41+a43);
  a41=(a41*a44);
  a48=(a48+a41);
  a42=(a42*a48);
  a24=(a24+a42);
  a42=arg[2]? arg[2][87] : 0;
  a41=(a16*a42);
  a44=arg[2]? arg[2][88] : 0;
  a43=(a01*a44);
  a41=(a41+a43);
  a43=arg[2]? arg[2][89] : 0;
  a49=(a00*a43);
  a41=(a41+a49);
  a49=arg[0]? arg[0][2] : 0;
  a50=(a41+a49);
  a51=(a50*a23);
  a52=arg[2]? arg[2][92] : 0;
  a53=(a26*a52);
  a54=arg[2]? arg[2][90] : 0;
  a05=(a05*a54);
  a53=(a53+a05);
  a05=arg[2]? arg[2][91] : 0;
  a20=(a20*a05);
  a53=(a53+a20);
  a20=(a53+a50);
  a55=(a20*a39);
  a51=(a51+a55);
  a55=(a34*a49);
  a51=(a51+a55);
  a51=(a24+a51);
  a49=(a51-a49);
  a55=(a11*a49);
  a56=(a13*a11);
  a57=(a18*a06);
  a56=(a56+a57);
  a57=(a12*a09);
  a56=(a56+a57);
  a57=(a56*a14);
  a58=(a19*a11);
  a59=(a21*a06);
  a58=(a58+a59);
  a59=(a22*a09);
  a58=(a58+a59);
  a59=(a58*a02);
  a57=(a57+a59);
  a59=(a57*a23);
  a60=(a25*a11);
  a61=(a27*a06);
  a60=(a60+a61);
  a61=(a28*a09);
  a60=(a60+a61);
  a61=(a60*a29);
  a62=(a31*a57);
  a61=(a61+a62);
  a58=(a58*a14);
  a56=(a56*a02);
  a58=(a58-a56);
  a56=(a32*a58);
  a61=(a61+a56);
  a56=(a61*a33);
  a62=(a60*a35);
  a63=(a37*a57);
  a62=(a62+a63);
  a63=(a38*a58);
  a62=(a62+a63);
  a63=(a62*a03);
  a56=(a56+a63);
  a56=(a56*a39);
  a59=(a59+a56);
  a56=(a11*a34);
  a59=(a59+a56);
  a59=(a59*a40);
  a56=(a58*a23);
  a62=(a62*a33);
  a61=(a61*a03);
  a62=(a62-a61);
  a62=(a62*a39);
  a56=(a56+a62);
  a62=(a06*a34);
  a56=(a56+a62);
  a56=(a56*a36);
  a59=(a59+a56);
  a56=(a60*a23);
  a62=(a60*a30);
  a61=(a46*a57);
  a62=(a62+a61);
  a61=(a47*a58);
  a62=(a62+a61);
  a61=(a62*a39);
  a56=(a56+a61);
  a61=(a09*a34);
  a56=(a56+a61);
  a56=(a56*a48);
  a59=(a59+a56);
  a56=(a11*a42);
  a61=(a06*a44);
  a56=(a56+a61);
  a61=(a09*a43);
  a56=(a56+a61);
  a61=arg[0]? arg[0][1] : 0;
  a63=(a56+a61);
  a64=(a63*a23);
  a65=(a60*a52);
  a57=(a57*a54);
  a65=(a65+a57);
  a58=(a58*a05);
  a65=(a65+a58);
  a58=(a65+a63);
  a57=(a58*a39);
  a64=(a64+a57);
  a57=(a34*a61);
  a64=(a64+a57);
  a64=(a59+a64);
  a61=(a64-a61);
  a57=(a16*a61);
  a55=(a55-a57);
  a55=(a07*a55);
  a13=(a13*a04);
  a18=(a18*a08);
  a13=(a13+a18);
  a12=(a12*a10);
  a13=(a13+a12);
  a12=(a13*a14);
  a19=(a19*a04);
  a21=(a21*a08);
  a19=(a19+a21);
  a22=(a22*a10);
  a19=(a19+a22);
  a22=(a19*a02);
  a12=(a12+a22);
  a22=(a12*a23);
  a25=(a25*a04);
  a27=(a27*a08);
  a25=(a25+a27);
  a28=(a28*a10);
  a25=(a25+a28);
  a29=(a25*a29);
  a31=(a31*a12);
  a29=(a29+a31);
  a19=(a19*a14);
  a13=(a13*a02);
  a19=(a19-a13);
  a32=(a32*a19);
  a29=(a29+a32);
  a32=(a29*a33);
  a35=(a25*a35);
  a37=(a37*a12);
  a35=(a35+a37);
  a38=(a38*a19);
  a35=(a35+a38);
  a38=(a35*a03);
  a32=(a32+a38);
  a32=(a32*a39);
  a22=(a22+a32);
  a32=(a04*a34);
  a22=(a22+a32);
  a22=(a22*a40);
  a40=(a19*a23);
  a35=(a35*a33);
  a29=(a29*a03);
  a35=(a35-a29);
  a35=(a35*a39);
  a40=(a40+a35);
  a35=(a08*a34);
  a40=(a40+a35);
  a40=(a40*a36);
  a22=(a22+a40);
  a40=(a25*a23);
  a30=(a25*a30);
  a46=(a46*a12);
  a30=(a30+a46);
  a47=(a47*a19);
  a30=(a30+a47);
  a47=(a30*a39);
  a40=(a40+a47);
  a47=(a10*a34);
  a40=(a40+a47);
  a40=(a40*a48);
  a22=(a22+a40);
  a42=(a04*a42);
  a44=(a08*a44);
  a42=(a42+a44);
  a43=(a10*a43);
  a42=(a42+a43);
  a43=arg[0]? arg[0][0] : 0;
  a44=(a42+a43);
  a40=(a44*a23);
  a52=(a25*a52);
  a12=(a12*a54);
  a52=(a52+a12);
  a19=(a19*a05);
  a52=(a52+a19);
  a19=(a52+a44);
  a05=(a19*a39);
  a40=(a40+a05);
  a05=(a34*a43);
  a40=(a40+a05);
  a40=(a22+a40);
  a43=(a40-a43);
  a05=(a16*a43);
  a12=(a04*a49);
  a05=(a05-a12);
  a05=(a15*a05);
  a55=(a55+a05);
  a05=(a04*a61);
  a12=(a11*a43);
  a05=(a05-a12);
  a05=(a17*a05);
  a55=(a55+a05);
  a55=(-a55);
  if (res[0]!=0) res[0][3]=a55;
  a55=(a06*a49);
  a05=(a01*a61);
  a55=(a55-a05);
  a55=(a07*a55);
  a05=(a01*a43);
  a12=(a08*a49);
  a05=(a05-a12);
  a05=(a15*a05);
  a55=(a55+a05);
  a05=(a08*a61);
  a12=(a06*a43);
  a05=(a05-a12);
  a05=(a17*a05);
  a55=(a55+a05);
  a55=(-a55);
  if (res[0]!=0) res[0][4]=a55;
  a55=(a09*a49);
  a05=(a00*a61);
  a55=(a55-a05);
  a55=(a07*a55);
  a05=(a00*a43);
  a49=(a10*a49);
  a05=(a05-a49);
  a05=(a15*a05);
  a55=(a55+a05);
  a61=(a10*a61);
  a43=(a09*a43);
  a61=(a61-a43);
  a61=(a17*a61);
  a55=(a55+a61);
  a55=(-a55);
  if (res[0]!=0) res[0][5]=a55;
  a55=(a23+a39);
  a61=(a55*a07);
  a50=(a51-a50);
  a43=(a60*a50);
  a63=(a64-a63);
  a05=(a26*a63);
  a43=(a43-a05);
  a61=(a61*a43);
  a43=(a55*a15);
  a44=(a40-a44);
  a05=(a26*a44);
  a50=(a25*a50);
  a05=(a05-a50);
  a43=(a43*a05);
  a61=(a61+a43);
  a55=(a55*a17);
  a63=(a25*a63);
  a44=(a60*a44);
  a63=(a63-a44);
  a55=(a55*a63);
  a61=(a61+a55);
  a61=(-a61);
  if (res[0]!=0) res[0][6]=a61;
  a61=(a07*a39);
  a20=(a51-a20);
  a55=(a62*a20);
  a58=(a64-a58);
  a63=(a45*a58);
  a55=(a55-a63);
  a61=(a61*a55);
  a55=(a15*a39);
  a19=(a40-a19);
  a63=(a45*a19);
  a20=(a30*a20);
  a63=(a63-a20);
  a55=(a55*a63);
  a61=(a61+a55);
  a55=(a17*a39);
  a58=(a30*a58);
  a19=(a62*a19);
  a58=(a58-a19);
  a55=(a55*a58);
  a61=(a61+a55);
  a61=(-a61);
  if (res[0]!=0) res[0][7]=a61;
  if (res[1]!=0) res[1][0]=a07;
  if (res[1]!=0) res[1][1]=a15;
  if (res[1]!=0) res[1][2]=a17;
  a61=arg[6]? arg[6][1] : 0;
  a55=(a17*a61);
  a58=arg[6]? arg[6][2] : 0;
  a19=(a15*a58);
  a55=(a55-a19);
  if (res[1]!=0) res[1][3]=a55;
  a55=(a07*a58);
  a19=arg[6]? arg[6][0] : 0;
  a63=(a17*a19);
  a55=(a55-a63);
  if (res[1]!=0) res[1][4]=a55;
  a55=(a15*a19);
  a63=(a07*a61);
  a55=(a55-a63);
  if (res[1]!=0) res[1][5]=a55;
  a55=arg[7]? arg[7][3] : 0;
  a63=(a61*a55);
  a20=arg[7]? arg[7][4] : 0;
  a44=(a19*a20);
  a63=(a63-a44);
  a44=(a63*a20);
  a43=arg[1]? arg[1][3] : 0;
  a05=(a11*a43);
  a50=arg[1]? arg[1][4] : 0;
  a49=(a06*a50);
  a05=(a05+a49);
  a49=arg[1]? arg[1][5] : 0;
  a12=(a09*a49);
  a05=(a05+a12);
  a12=arg[1]? arg[1][0] : 0;
  a54=(a16*a12);
  a48=arg[1]? arg[1][1] : 0;
  a47=(a01*a48);
  a54=(a54+a47);
  a47=arg[1]? arg[1][2] : 0;
  a46=(a00*a47);
  a54=(a54+a46);
  a46=(a05*a54);
  a16=(a16*a43);
  a01=(a01*a50);
  a16=(a16+a01);
  a00=(a00*a49);
  a16=(a16+a00);
  a11=(a11*a12);
  a06=(a06*a48);
  a11=(a11+a06);
  a09=(a09*a47);
  a11=(a11+a09);
  a09=(a16*a11);
  a46=(a46-a09);
  a09=(a46*a34);
  a43=(a04*a43);
  a50=(a08*a50);
  a43=(a43+a50);
  a49=(a10*a49);
  a43=(a43+a49);
  a49=(a56*a43);
  a50=(a42*a05);
  a06=(a49-a50);
  a00=(a05*a06);
  a46=(a46+a00);
  a42=(a42*a16);
  a00=(a41*a43);
  a01=(a42-a00);
  a36=(a16*a01);
  a46=(a46-a36);
  a36=(a46*a23);
  a09=(a09+a36);
  a36=arg[1]? arg[1][6] : 0;
  a35=(a25*a16);
  a29=(a26*a43);
  a35=(a35-a29);
  a35=(a36*a35);
  a29=(a35*a53);
  a46=(a46+a29);
  a29=(a60*a36);
  a29=(a05+a29);
  a03=(a25*a36);
  a03=(a43+a03);
  a33=(a65*a03);
  a32=(a52*a29);
  a38=(a33-a32);
  a37=(a29*a38);
  a46=(a46+a37);
  a37=(a60*a43);
  a25=(a25*a05);
  a37=(a37-a25);
  a37=(a36*a37);
  a25=(a37*a65);
  a46=(a46-a25);
  a25=(a26*a36);
  a25=(a16+a25);
  a13=(a52*a25);
  a02=(a53*a03);
  a14=(a13-a02);
  a31=(a25*a14);
  a46=(a46-a31);
  a46=(a46*a39);
  a09=(a09+a46);
  a46=(a35*a23);
  a31=arg[1]? arg[1][7] : 0;
  a28=(a30*a25);
  a27=(a45*a03);
  a28=(a28-a27);
  a28=(a31*a28);
  a28=(a35+a28);
  a28=(a28*a39);
  a46=(a46+a28);
  a28=(a46*a24);
  a09=(a09+a28);
  a28=(a05*a34);
  a27=(a29*a23);
  a28=(a28+a27);
  a27=(a62*a31);
  a27=(a29+a27);
  a27=(a27*a39);
  a28=(a28+a27);
  a27=(a43*a34);
  a21=(a03*a23);
  a27=(a27+a21);
  a21=(a30*a31);
  a21=(a03+a21);
  a21=(a21*a39);
  a27=(a27+a21);
  a21=(a59*a27);
  a18=(a22*a28);
  a57=(a21-a18);
  a66=(a28*a57);
  a09=(a09+a66);
  a66=(a37*a23);
  a67=(a62*a03);
  a30=(a30*a29);
  a67=(a67-a30);
  a67=(a31*a67);
  a67=(a37+a67);
  a67=(a67*a39);
  a66=(a66+a67);
  a67=(a66*a59);
  a09=(a09-a67);
  a67=(a16*a34);
  a30=(a25*a23);
  a67=(a67+a30);
  a30=(a45*a31);
  a30=(a25+a30);
  a30=(a30*a39);
  a67=(a67+a30);
  a30=(a22*a67);
  a68=(a24*a27);
  a69=(a30-a68);
  a70=(a67*a69);
  a09=(a09-a70);
  a44=(a44-a09);
  a09=arg[7]? arg[7][5] : 0;
  a19=(a19*a09);
  a70=(a58*a55);
  a19=(a19-a70);
  a70=(a19*a09);
  a44=(a44-a70);
  a44=(a07*a44);
  a58=(a58*a20);
  a61=(a61*a09);
  a58=(a58-a61);
  a61=(a58*a09);
  a04=(a04*a12);
  a08=(a08*a48);
  a04=(a04+a08);
  a10=(a10*a47);
  a04=(a04+a10);
  a10=(a16*a04);
  a47=(a43*a54);
  a10=(a10-a47);
  a47=(a10*a34);
  a41=(a41*a05);
  a56=(a56*a16);
  a08=(a41-a56);
  a48=(a16*a08);
  a10=(a10+a48);
  a06=(a43*a06);
  a10=(a10-a06);
  a06=(a10*a23);
  a47=(a47+a06);
  a37=(a37*a52);
  a10=(a10+a37);
  a37=(a53*a29);
  a06=(a65*a25);
  a48=(a37-a06);
  a12=(a25*a48);
  a10=(a10+a12);
  a26=(a26*a05);
  a60=(a60*a16);
  a26=(a26-a60);
  a36=(a36*a26);
  a53=(a36*a53);
  a10=(a10-a53);
  a38=(a03*a38);
  a10=(a10-a38);
  a10=(a10*a39);
  a47=(a47+a10);
  a66=(a66*a22);
  a47=(a47+a66);
  a66=(a24*a28);
  a10=(a59*a67);
  a38=(a66-a10);
  a67=(a67*a38);
  a47=(a47+a67);
  a67=(a36*a23);
  a45=(a45*a29);
  a62=(a62*a25);
  a45=(a45-a62);
  a31=(a31*a45);
  a31=(a36+a31);
  a31=(a31*a39);
  a67=(a67+a31);
  a24=(a67*a24);
  a47=(a47-a24);
  a57=(a27*a57);
  a47=(a47-a57);
  a61=(a61-a47);
  a47=(a63*a55);
  a61=(a61-a47);
  a61=(a15*a61);
  a44=(a44+a61);
  a61=(a19*a55);
  a47=(a43*a11);
  a57=(a05*a04);
  a47=(a47-a57);
  a57=(a47*a34);
  a43=(a43*a01);
  a47=(a47+a43);
  a05=(a05*a08);
  a47=(a47-a05);
  a05=(a47*a23);
  a57=(a57+a05);
  a36=(a36*a65);
  a47=(a47+a36);
  a03=(a03*a14);
  a47=(a47+a03);
  a35=(a35*a52);
  a47=(a47-a35);
  a29=(a29*a48);
  a47=(a47-a29);
  a47=(a47*a39);
  a57=(a57+a47);
  a67=(a67*a59);
  a57=(a57+a67);
  a27=(a27*a69);
  a57=(a57+a27);
  a46=(a46*a22);
  a57=(a57-a46);
  a28=(a28*a38);
  a57=(a57-a28);
  a61=(a61-a57);
  a57=(a58*a20);
  a61=(a61-a57);
  a61=(a17*a61);
  a44=(a44+a61);
  a61=(a07*a09);
  a57=(a17*a55);
  a61=(a61-a57);
  a57=arg[7]? arg[7][1] : 0;
  a19=(a19+a57);
  a57=(a34*a11);
  a11=(a11+a42);
  a11=(a11-a00);
  a00=(a23*a11);
  a57=(a57+a00);
  a11=(a11+a13);
  a11=(a11-a02);
  a11=(a39*a11);
  a57=(a57+a11);
  a57=(a57+a30);
  a57=(a57-a68);
  a19=(a19-a57);
  a61=(a61*a19);
  a44=(a44+a61);
  a55=(a15*a55);
  a07=(a07*a20);
  a55=(a55-a07);
  a07=arg[7]? arg[7][2] : 0;
  a63=(a63+a07);
  a07=(a34*a54);
  a54=(a54+a49);
  a54=(a54-a50);
  a50=(a23*a54);
  a07=(a07+a50);
  a54=(a54+a33);
  a54=(a54-a32);
  a54=(a39*a54);
  a07=(a07+a54);
  a07=(a07+a21);
  a07=(a07-a18);
  a63=(a63-a07);
  a55=(a55*a63);
  a44=(a44+a55);
  a17=(a17*a20);
  a15=(a15*a09);
  a17=(a17-a15);
  a15=arg[7]? arg[7][0] : 0;
  a58=(a58+a15);
  a34=(a34*a04);
  a04=(a04+a41);
  a04=(a04-a56);
  a23=(a23*a04);
  a34=(a34+a23);
  a04=(a04+a37);
  a04=(a04-a06);
  a39=(a39*a04);
  a34=(a34+a39);
  a34=(a34+a66);
  a34=(a34-a10);
  a58=(a58-a34);
  a17=(a17*a58);
  a44=(a44+a17);
  if (res[2]!=0) res[2][0]=a44;
  if (res[3]!=0) res[3][0]=a40;
  if (res[3]!=0) res[3][1]=a64;
  if (res[3]!=0) res[3][2]=a51;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_contact_row(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_contact_row_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_contact_row_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_contact_row_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_contact_row_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_contact_row_n_in(void) { return 8;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_contact_row_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_contact_row_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_contact_row_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "link";
    case 4: return "point";
    case 5: return "normal";
    case 6: return "rho";
    case 7: return "v_obj";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_contact_row_name_out(casadi_int i) {
  switch (i) {
    case 0: return "a_snake";
    case 1: return "g_obj";
    case 2: return "adot_v";
    case 3: return "position";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_contact_row_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    case 6: return casadi_s3;
    case 7: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_contact_row_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s6;
    case 2: return casadi_s7;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_contact_row_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_contact_row_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 8*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
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

/* snakecg_sp2_contact_row_sincos: 816 CasADi instructions, printed one per line */
static void snakecg_sp2_contact_row_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    const casadi_real* restrict arg6,
    const casadi_real* restrict arg7,
    const casadi_real* restrict arg8,
    const casadi_real* restrict arg9,
    casadi_real* restrict res0,
    casadi_real* restrict res1,
    casadi_real* restrict res2,
    casadi_real* restrict res3) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58, w59;
  casadi_real w60, w61, w62, w63, w64, w65, w66, w67, w68, w69;
  casadi_real w70;
  w0 = 1.0;
  w1 = (-2.0);
  w2 = arg0[4];
  w3 = w2 * w2;
  w3 = w1 * w3;
  w4 = w0 + w3;
  w5 = arg0[5];
  w6 = w5 * w5;
  w6 = w1 * w6;
  w4 = w4 + w6;
  w7 = arg5[0];
  w8 = w4 * w7;
  w9 = arg0[6];
  w10 = w9 + w9;
  w11 = w10 * w5;
  w12 = arg0[3];
  w13 = w12 + w12;
  w14 = w13 * w2;
  w11 = w11 + w14;
  w15 = arg5[1];
  w16 = w11 * w15;
  w8 = w8 + w16;
  w9 = w1 * w9;
  w16 = w9 * w2;
  w13 = w13 * w5;
  w16 = w16 + w13;
  w17 = arg5[2];
  w18 = w16 * w17;
  w8 = w8 + w18;
  w8 = -w8;
  res0[0] = w8;
  w8 = w9 * w5;
  w8 = w8 + w14;
  w14 = w8 * w7;
  w18 = w12 * w12;
  w1 = w1 * w18;
  w0 = w0 + w1;
  w6 = w0 + w6;
  w1 = w6 * w15;
  w14 = w14 + w1;
  w1 = w10 * w12;
  w18 = w2 + w2;
  w18 = w18 * w5;
  w1 = w1 + w18;
  w5 = w1 * w17;
  w14 = w14 + w5;
  w14 = -w14;
  res0[1] = w14;
  w10 = w10 * w2;
  w10 = w10 + w13;
  w13 = w10 * w7;
  w9 = w9 * w12;
  w9 = w9 + w18;
  w18 = w9 * w15;
  w13 = w13 + w18;
  w0 = w0 + w3;
  w3 = w0 * w17;
  w13 = w13 + w3;
  w13 = -w13;
  res0[2] = w13;
  w13 = arg2[69];
  w3 = w13 * w16;
  w18 = arg2[70];
  w12 = w18 * w1;
  w3 = w3 + w12;
  w12 = arg2[71];
  w2 = w12 * w0;
  w3 = w3 + w2;
  w2 = arg8[0];
  w14 = w3 * w2;
  w5 = arg2[72];
  w19 = w5 * w16;
  w20 = arg2[73];
  w21 = w20 * w1;
  w19 = w19 + w21;
  w21 = arg2[74];
  w22 = w21 * w0;
  w19 = w19 + w22;
  w22 = arg9[0];
  w23 = w19 * w22;
  w14 = w14 + w23;
  w23 = arg3[1];
  w24 = w14 * w23;
  w25 = arg2[75];
  w26 = w25 * w16;
  w27 = arg2[76];
  w28 = w27 * w1;
  w26 = w26 + w28;
  w28 = arg2[77];
  w29 = w28 * w0;
  w26 = w26 + w29;
  w29 = arg2[80];
  w30 = w26 * w29;
  w31 = arg2[78];
  w32 = w31 * w14;
  w30 = w30 + w32;
  w32 = arg2[79];
  w19 = w19 * w2;
  w3 = w3 * w22;
  w19 = w19 - w3;
  w3 = w32 * w19;
  w30 = w30 + w3;
  w3 = arg8[1];
  w33 = w30 * w3;
  w34 = arg2[83];
  w35 = w26 * w34;
  w36 = arg2[81];
  w37 = w36 * w14;
  w35 = w35 + w37;
  w37 = arg2[82];
  w38 = w37 * w19;
  w35 = w35 + w38;
  w38 = arg9[1];
  w39 = w35 * w38;
  w33 = w33 + w39;
  w39 = arg3[2];
  w33 = w33 * w39;
  w24 = w24 + w33;
  w33 = arg3[0];
  w40 = w16 * w33;
  w24 = w24 + w40;
  w40 = arg2[51];
  w40 = w40 * w23;
  w40 = w33 + w40;
  w41 = arg2[60];
  w41 = w41 * w39;
  w40 = w40 + w41;
  w41 = arg4[0];
  w40 = w40 * w41;
  w42 = arg2[52];
  w42 = w42 * w23;
  w43 = arg2[61];
  w43 = w43 * w39;
  w42 = w42 + w43;
  w43 = arg4[1];
  w42 = w42 * w43;
  w40 = w40 + w42;
  w42 = arg2[53];
  w42 = w42 * w23;
  w44 = arg2[62];
  w44 = w44 * w39;
  w42 = w42 + w44;
  w44 = arg4[2];
  w42 = w42 * w44;
  w40 = w40 + w42;
  w24 = w24 * w40;
  w42 = w19 * w23;
  w35 = w35 * w3;
  w30 = w30 * w38;
  w35 = w35 - w30;
  w35 = w35 * w39;
  w42 = w42 + w35;
  w35 = w1 * w33;
  w42 = w42 + w35;
  w35 = arg2[54];
  w35 = w35 * w23;
  w30 = arg2[63];
  w30 = w30 * w39;
  w35 = w35 + w30;
  w35 = w35 * w41;
  w30 = arg2[55];
  w30 = w30 * w23;
  w30 = w33 + w30;
  w45 = arg2[64];
  w45 = w45 * w39;
  w30 = w30 + w45;
  w30 = w30 * w43;
  w35 = w35 + w30;
  w30 = arg2[56];
  w30 = w30 * w23;
  w45 = arg2[65];
  w45 = w45 * w39;
  w30 = w30 + w45;
  w30 = w30 * w44;
  w35 = w35 + w30;
  w42 = w42 * w35;
  w24 = w24 + w42;
  w42 = w26 * w23;
  w30 = arg2[86];
  w45 = w26 * w30;
  w46 = arg2[84];
  w47 = w46 * w14;
  w45 = w45 + w47;
  w47 = arg2[85];
  w48 = w47 * w19;
  w45 = w45 + w48;
  w48 = w45 * w39;
  w42 = w42 + w48;
  w48 = w0 * w33;
  w42 = w42 + w48;
  w48 = arg2[57];
  w48 = w48 * w23;
  w49 = arg2[66];
  w49 = w49 * w39;
  w48 = w48 + w49;
  w48 = w48 * w41;
  w41 = arg2[58];
  w41 = w41 * w23;
  w49 = arg2[67];
  w49 = w49 * w39;
  w41 = w41 + w49;
  w41 = w41 * w43;
  w48 = w48 + w41;
  w41 = arg2[59];
  w41 = w41 * w23;
  w41 = w33 + w41;
  w43 = arg2[68];
  w43 = w43 * w39;
  w41 = w41 + w43;
  w41 = w41 * w44;
  w48 = w48 + w41;
  w42 = w42 * w48;
  w24 = w24 + w42;
  w42 = arg2[87];
  w41 = w16 * w42;
  w44 = arg2[88];
  w43 = w1 * w44;
  w41 = w41 + w43;
  w43 = arg2[89];
  w49 = w0 * w43;
  w41 = w41 + w49;
  w49 = arg0[2];
  w50 = w41 + w49;
  w51 = w50 * w23;
  w52 = arg2[92];
  w53 = w26 * w52;
  w54 = arg2[90];
  w14 = w14 * w54;
  w53 = w53 + w14;
  w14 = arg2[91];
  w19 = w19 * w14;
  w53 = w53 + w19;
  w19 = w53 + w50;
  w55 = w19 * w39;
  w51 = w51 + w55;
  w55 = w33 * w49;
  w51 = w51 + w55;
  w51 = w24 + w51;
  w49 = w51 - w49;
  w55 = w11 * w49;
  w56 = w13 * w11;
  w57 = w18 * w6;
  w56 = w56 + w57;
  w57 = w12 * w9;
  w56 = w56 + w57;
  w57 = w56 * w2;
  w58 = w5 * w11;
  w59 = w20 * w6;
  w58 = w58 + w59;
  w59 = w21 * w9;
  w58 = w58 + w59;
  w59 = w58 * w22;
  w57 = w57 + w59;
  w59 = w57 * w23;
  w60 = w25 * w11;
  w61 = w27 * w6;
  w60 = w60 + w61;
  w61 = w28 * w9;
  w60 = w60 + w61;
  w61 = w60 * w29;
  w62 = w31 * w57;
  w61 = w61 + w62;
  w58 = w58 * w2;
  w56 = w56 * w22;
  w58 = w58 - w56;
  w56 = w32 * w58;
  w61 = w61 + w56;
  w56 = w61 * w3;
  w62 = w60 * w34;
  w63 = w36 * w57;
  w62 = w62 + w63;
  w63 = w37 * w58;
  w62 = w62 + w63;
  w63 = w62 * w38;
  w56 = w56 + w63;
  w56 = w56 * w39;
  w59 = w59 + w56;
  w56 = w11 * w33;
  w59 = w59 + w56;
  w59 = w59 * w40;
  w56 = w58 * w23;
  w62 = w62 * w3;
  w61 = w61 * w38;
  w62 = w62 - w61;
  w62 = w62 * w39;
  w56 = w56 + w62;
  w62 = w6 * w33;
  w56 = w56 + w62;
  w56 = w56 * w35;
  w59 = w59 + w56;
  w56 = w60 * w23;
  w62 = w60 * w30;
  w61 = w46 * w57;
  w62 = w62 + w61;
  w61 = w47 * w58;
  w62 = w62 + w61;
  w61 = w62 * w39;
  w56 = w56 + w61;
  w61 = w9 * w33;
  w56 = w56 + w61;
  w56 = w56 * w48;
  w59 = w59 + w56;
  w56 = w11 * w42;
  w61 = w6 * w44;
  w56 = w56 + w61;
  w61 = w9 * w43;
  w56 = w56 + w61;
  w61 = arg0[1];
  w63 = w56 + w61;
  w64 = w63 * w23;
  w65 = w60 * w52;
  w57 = w57 * w54;
  w65 = w65 + w57;
  w58 = w58 * w14;
  w65 = w65 + w58;
  w58 = w65 + w63;
  w57 = w58 * w39;
  w64 = w64 + w57;
  w57 = w33 * w61;
  w64 = w64 + w57;
  w64 = w59 + w64;
  w61 = w64 - w61;
  w57 = w16 * w61;
  w55 = w55 - w57;
  w55 = w7 * w55;
  w13 = w13 * w4;
  w18 = w18 * w8;
  w13 = w13 + w18;
  w12 = w12 * w10;
  w13 = w13 + w12;
  w12 = w13 * w2;
  w5 = w5 * w4;
  w20 = w20 * w8;
  w5 = w5 + w20;
  w21 = w21 * w10;
  w5 = w5 + w21;
  w21 = w5 * w22;
  w12 = w12 + w21;
  w21 = w12 * w23;
  w25 = w25 * w4;
  w27 = w27 * w8;
  w25 = w25 + w27;
  w28 = w28 * w10;
  w25 = w25 + w28;
  w29 = w25 * w29;
  w31 = w31 * w12;
  w29 = w29 + w31;
  w5 = w5 * w2;
  w13 = w13 * w22;
  w5 = w5 - w13;
  w32 = w32 * w5;
  w29 = w29 + w32;
  w32 = w29 * w3;
  w34 = w25 * w34;
  w36 = w36 * w12;
  w34 = w34 + w36;
  w37 = w37 * w5;
  w34 = w34 + w37;
  w37 = w34 * w38;
  w32 = w32 + w37;
  w32 = w32 * w39;
  w21 = w21 + w32;
  w32 = w4 * w33;
  w21 = w21 + w32;
  w21 = w21 * w40;
  w40 = w5 * w23;
  w34 = w34 * w3;
  w29 = w29 * w38;
  w34 = w34 - w29;
  w34 = w34 * w39;
  w40 = w40 + w34;
  w34 = w8 * w33;
  w40 = w40 + w34;
  w40 = w40 * w35;
  w21 = w21 + w40;
  w40 = w25 * w23;
  w30 = w25 * w30;
  w46 = w46 * w12;
  w30 = w30 + w46;
  w47 = w47 * w5;
  w30 = w30 + w47;
  w47 = w30 * w39;
  w40 = w40 + w47;
  w47 = w10 * w33;
  w40 = w40 + w47;
  w40 = w40 * w48;
  w21 = w21 + w40;
  w42 = w4 * w42;
  w44 = w8 * w44;
  w42 = w42 + w44;
  w43 = w10 * w43;
  w42 = w42 + w43;
  w43 = arg0[0];
  w44 = w42 + w43;
  w40 = w44 * w23;
  w52 = w25 * w52;
  w12 = w12 * w54;
  w52 = w52 + w12;
  w5 = w5 * w14;
  w52 = w52 + w5;
  w5 = w52 + w44;
  w14 = w5 * w39;
  w40 = w40 + w14;
  w14 = w33 * w43;
  w40 = w40 + w14;
  w40 = w21 + w40;
  w43 = w40 - w43;
  w14 = w16 * w43;
  w12 = w4 * w49;
  w14 = w14 - w12;
  w14 = w15 * w14;
  w55 = w55 + w14;
  w14 = w4 * w61;
  w12 = w11 * w43;
  w14 = w14 - w12;
  w14 = w17 * w14;
  w55 = w55 + w14;
  w55 = -w55;
  res0[3] = w55;
  w55 = w6 * w49;
  w14 = w1 * w61;
  w55 = w55 - w14;
  w55 = w7 * w55;
  w14 = w1 * w43;
  w12 = w8 * w49;
  w14 = w14 - w12;
  w14 = w15 * w14;
  w55 = w55 + w14;
  w14 = w8 * w61;
  w12 = w6 * w43;
  w14 = w14 - w12;
  w14 = w17 * w14;
  w55 = w55 + w14;
  w55 = -w55;
  res0[4] = w55;
  w55 = w9 * w49;
  w14 = w0 * w61;
  w55 = w55 - w14;
  w55 = w7 * w55;
  w14 = w0 * w43;
  w49 = w10 * w49;
  w14 = w14 - w49;
  w14 = w15 * w14;
  w55 = w55 + w14;
  w61 = w10 * w61;
  w43 = w9 * w43;
  w61 = w61 - w43;
  w61 = w17 * w61;
  w55 = w55 + w61;
  w55 = -w55;
  res0[5] = w55;
  w55 = w23 + w39;
  w61 = w55 * w7;
  w50 = w51 - w50;
  w43 = w60 * w50;
  w63 = w64 - w63;
  w14 = w26 * w63;
  w43 = w43 - w14;
  w61 = w61 * w43;
  w43 = w55 * w15;
  w44 = w40 - w44;
  w14 = w26 * w44;
  w50 = w25 * w50;
  w14 = w14 - w50;
  w43 = w43 * w14;
  w61 = w61 + w43;
  w55 = w55 * w17;
  w63 = w25 * w63;
  w44 = w60 * w44;
  w63 = w63 - w44;
  w55 = w55 * w63;
  w61 = w61 + w55;
  w61 = -w61;
  res0[6] = w61;
  w61 = w7 * w39;
  w19 = w51 - w19;
  w55 = w62 * w19;
  w58 = w64 - w58;
  w63 = w45 * w58;
  w55 = w55 - w63;
  w61 = w61 * w55;
  w55 = w15 * w39;
  w5 = w40 - w5;
  w63 = w45 * w5;
  w19 = w30 * w19;
  w63 = w63 - w19;
  w55 = w55 * w63;
  w61 = w61 + w55;
  w55 = w17 * w39;
  w58 = w30 * w58;
  w5 = w62 * w5;
  w58 = w58 - w5;
  w55 = w55 * w58;
  w61 = w61 + w55;
  w61 = -w61;
  res0[7] = w61;
  res1[0] = w7;
  res1[1] = w15;
  res1[2] = w17;
  w61 = arg6[1];
  w55 = w17 * w61;
  w58 = arg6[2];
  w5 = w15 * w58;
  w55 = w55 - w5;
  res1[3] = w55;
  w55 = w7 * w58;
  w5 = arg6[0];
  w63 = w17 * w5;
  w55 = w55 - w63;
  res1[4] = w55;
  w55 = w15 * w5;
  w63 = w7 * w61;
  w55 = w55 - w63;
  res1[5] = w55;
  w55 = arg7[3];
  w63 = w61 * w55;
  w19 = arg7[4];
  w44 = w5 * w19;
  w63 = w63 - w44;
  w44 = w63 * w19;
  w43 = arg1[3];
  w14 = w11 * w43;
  w50 = arg1[4];
  w49 = w6 * w50;
  w14 = w14 + w49;
  w49 = arg1[5];
  w12 = w9 * w49;
  w14 = w14 + w12;
  w12 = arg1[0];
  w54 = w16 * w12;
  w48 = arg1[1];
  w47 = w1 * w48;
  w54 = w54 + w47;
  w47 = arg1[2];
  w46 = w0 * w47;
  w54 = w54 + w46;
  w46 = w14 * w54;
  w16 = w16 * w43;
  w1 = w1 * w50;
  w16 = w16 + w1;
  w0 = w0 * w49;
  w16 = w16 + w0;
  w11 = w11 * w12;
  w6 = w6 * w48;
  w11 = w11 + w6;
  w9 = w9 * w47;
  w11 = w11 + w9;
  w9 = w16 * w11;
  w46 = w46 - w9;
  w9 = w46 * w33;
  w43 = w4 * w43;
  w50 = w8 * w50;
  w43 = w43 + w50;
  w49 = w10 * w49;
  w43 = w43 + w49;
  w49 = w56 * w43;
  w50 = w42 * w14;
  w6 = w49 - w50;
  w0 = w14 * w6;
  w46 = w46 + w0;
  w42 = w42 * w16;
  w0 = w41 * w43;
  w1 = w42 - w0;
  w35 = w16 * w1;
  w46 = w46 - w35;
  w35 = w46 * w23;
  w9 = w9 + w35;
  w35 = arg1[6];
  w34 = w25 * w16;
  w29 = w26 * w43;
  w34 = w34 - w29;
  w34 = w35 * w34;
  w29 = w34 * w53;
  w46 = w46 + w29;
  w29 = w60 * w35;
  w29 = w14 + w29;
  w38 = w25 * w35;
  w38 = w43 + w38;
  w3 = w65 * w38;
  w32 = w52 * w29;
  w37 = w3 - w32;
  w36 = w29 * w37;
  w46 = w46 + w36;
  w36 = w60 * w43;
  w25 = w25 * w14;
  w36 = w36 - w25;
  w36 = w35 * w36;
  w25 = w36 * w65;
  w46 = w46 - w25;
  w25 = w26 * w35;
  w25 = w16 + w25;
  w13 = w52 * w25;
  w22 = w53 * w38;
  w2 = w13 - w22;
  w31 = w25 * w2;
  w46 = w46 - w31;
  w46 = w46 * w39;
  w9 = w9 + w46;
  w46 = w34 * w23;
  w31 = arg1[7];
  w28 = w30 * w25;
  w27 = w45 * w38;
  w28 = w28 - w27;
  w28 = w31 * w28;
  w28 = w34 + w28;
  w28 = w28 * w39;
  w46 = w46 + w28;
  w28 = w46 * w24;
  w9 = w9 + w28;
  w28 = w14 * w33;
  w27 = w29 * w23;
  w28 = w28 + w27;
  w27 = w62 * w31;
  w27 = w29 + w27;
  w27 = w27 * w39;
  w28 = w28 + w27;
  w27 = w43 * w33;
  w20 = w38 * w23;
  w27 = w27 + w20;
  w20 = w30 * w31;
  w20 = w38 + w20;
  w20 = w20 * w39;
  w27 = w27 + w20;
  w20 = w59 * w27;
  w18 = w21 * w28;
  w57 = w20 - w18;
  w66 = w28 * w57;
  w9 = w9 + w66;
  w66 = w36 * w23;
  w67 = w62 * w38;
  w30 = w30 * w29;
  w67 = w67 - w30;
  w67 = w31 * w67;
  w67 = w36 + w67;
  w67 = w67 * w39;
  w66 = w66 + w67;
  w67 = w66 * w59;
  w9 = w9 - w67;
  w67 = w16 * w33;
  w30 = w25 * w23;
  w67 = w67 + w30;
  w30 = w45 * w31;
  w30 = w25 + w30;
  w30 = w30 * w39;
  w67 = w67 + w30;
  w30 = w21 * w67;
  w68 = w24 * w27;
  w69 = w30 - w68;
  w70 = w67 * w69;
  w9 = w9 - w70;
  w44 = w44 - w9;
  w9 = arg7[5];
  w5 = w5 * w9;
  w70 = w58 * w55;
  w5 = w5 - w70;
  w70 = w5 * w9;
  w44 = w44 - w70;
  w44 = w7 * w44;
  w58 = w58 * w19;
  w61 = w61 * w9;
  w58 = w58 - w61;
  w61 = w58 * w9;
  w4 = w4 * w12;
  w8 = w8 * w48;
  w4 = w4 + w8;
  w10 = w10 * w47;
  w4 = w4 + w10;
  w10 = w16 * w4;
  w47 = w43 * w54;
  w10 = w10 - w47;
  w47 = w10 * w33;
  w41 = w41 * w14;
  w56 = w56 * w16;
  w8 = w41 - w56;
  w48 = w16 * w8;
  w10 = w10 + w48;
  w6 = w43 * w6;
  w10 = w10 - w6;
  w6 = w10 * w23;
  w47 = w47 + w6;
  w36 = w36 * w52;
  w10 = w10 + w36;
  w36 = w53 * w29;
  w6 = w65 * w25;
  w48 = w36 - w6;
  w12 = w25 * w48;
  w10 = w10 + w12;
  w26 = w26 * w14;
  w60 = w60 * w16;
  w26 = w26 - w60;
  w35 = w35 * w26;
  w53 = w35 * w53;
  w10 = w10 - w53;
  w37 = w38 * w37;
  w10 = w10 - w37;
  w10 = w10 * w39;
  w47 = w47 + w10;
  w66 = w66 * w21;
  w47 = w47 + w66;
  w66 = w24 * w28;
  w10 = w59 * w67;
  w37 = w66 - w10;
  w67 = w67 * w37;
  w47 = w47 + w67;
  w67 = w35 * w23;
  w45 = w45 * w29;
  w62 = w62 * w25;
  w45 = w45 - w62;
  w31 = w31 * w45;
  w31 = w35 + w31;
  w31 = w31 * w39;
  w67 = w67 + w31;
  w24 = w67 * w24;
  w47 = w47 - w24;
  w57 = w27 * w57;
  w47 = w47 - w57;
  w61 = w61 - w47;
  w47 = w63 * w55;
  w61 = w61 - w47;
  w61 = w15 * w61;
  w44 = w44 + w61;
  w61 = w5 * w55;
  w47 = w43 * w11;
  w57 = w14 * w4;
  w47 = w47 - w57;
  w57 = w47 * w33;
  w43 = w43 * w1;
  w47 = w47 + w43;
  w14 = w14 * w8;
  w47 = w47 - w14;
  w14 = w47 * w23;
  w57 = w57 + w14;
  w35 = w35 * w65;
  w47 = w47 + w35;
  w38 = w38 * w2;
  w47 = w47 + w38;
  w34 = w34 * w52;
  w47 = w47 - w34;
  w29 = w29 * w48;
  w47 = w47 - w29;
  w47 = w47 * w39;
  w57 = w57 + w47;
  w67 = w67 * w59;
  w57 = w57 + w67;
  w27 = w27 * w69;
  w57 = w57 + w27;
  w46 = w46 * w21;
  w57 = w57 - w46;
  w28 = w28 * w37;
  w57 = w57 - w28;
  w61 = w61 - w57;
  w57 = w58 * w19;
  w61 = w61 - w57;
  w61 = w17 * w61;
  w44 = w44 + w61;
  w61 = w7 * w9;
  w57 = w17 * w55;
  w61 = w61 - w57;
  w57 = arg7[1];
  w5 = w5 + w57;
  w57 = w33 * w11;
  w11 = w11 + w42;
  w11 = w11 - w0;
  w0 = w23 * w11;
  w57 = w57 + w0;
  w11 = w11 + w13;
  w11 = w11 - w22;
  w11 = w39 * w11;
  w57 = w57 + w11;
  w57 = w57 + w30;
  w57 = w57 - w68;
  w5 = w5 - w57;
  w61 = w61 * w5;
  w44 = w44 + w61;
  w55 = w15 * w55;
  w7 = w7 * w19;
  w55 = w55 - w7;
  w7 = arg7[2];
  w63 = w63 + w7;
  w7 = w33 * w54;
  w54 = w54 + w49;
  w54 = w54 - w50;
  w50 = w23 * w54;
  w7 = w7 + w50;
  w54 = w54 + w3;
  w54 = w54 - w32;
  w54 = w39 * w54;
  w7 = w7 + w54;
  w7 = w7 + w20;
  w7 = w7 - w18;
  w63 = w63 - w7;
  w55 = w55 * w63;
  w44 = w44 + w55;
  w17 = w17 * w19;
  w15 = w15 * w9;
  w17 = w17 - w15;
  w15 = arg7[0];
  w58 = w58 + w15;
  w33 = w33 * w4;
  w4 = w4 + w41;
  w4 = w4 - w56;
  w23 = w23 * w4;
  w33 = w33 + w23;
  w4 = w4 + w36;
  w4 = w4 - w6;
  w39 = w39 * w4;
  w33 = w33 + w39;
  w33 = w33 + w66;
  w33 = w33 - w10;
  w58 = w58 - w33;
  w17 = w17 * w58;
  w44 = w44 + w17;
  res2[0] = w44;
  res3[0] = w40;
  res3[1] = w64;
  res3[2] = w51;
}


CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_contact_row(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[8];
  casadi_real* r[4];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 72);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 8; ++k) a[k] = 0;
  for (k = 0; k < 4; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && arg[4] && arg[5] && arg[6] && arg[7] && res[0] && res[1] && res[2] && res[3]) {
    /* cos and sin of q[7..8] of 16 samples at a time, then snakecg_sp2_contact_row_sincos
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
        snakecg_sp2_contact_row_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], arg[4] + (i0 + i) * stride[4], arg[5] + (i0 + i) * stride[5], arg[6] + (i0 + i) * stride[6], arg[7] + (i0 + i) * stride[7], ca + i * na, sa + i * na, res[0] + (i0 + i) * 8, res[1] + (i0 + i) * 6, res[2] + (i0 + i) * 1, res[3] + (i0 + i) * 3);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      a[4] = arg[4] + i * stride[4];
      a[5] = arg[5] + i * stride[5];
      a[6] = arg[6] + i * stride[6];
      a[7] = arg[7] + i * stride[7];
      r[0] = res[0] + i * 8;
      r[1] = res[1] + i * 6;
      r[2] = res[2] + i * 1;
      r[3] = res[3] + i * 3;
      if (snakecg_sp2_contact_row(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
