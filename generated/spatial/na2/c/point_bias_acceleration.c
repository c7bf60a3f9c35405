/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for point_bias_acceleration() of
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
  #define CASADI_PREFIX(ID) snakecg_sp2_point_bias_acceleration_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp2_point_bias_acceleration_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_point_bias_acceleration_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_point_bias_acceleration_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {8, 1, 1};
static const casadi_int casadi_s2[3] = {120, 1, 1};
static const casadi_int casadi_s3[3] = {3, 1, 1};

/* snakecg_sp2_point_bias_acceleration:(q[9],v[8],K[120],link[3],point[3])->(bias[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65;
  a00=arg[0]? arg[0][6] : 0;
  a01=(2.*a00);
  a02=arg[0]? arg[0][5] : 0;
  a03=(a01*a02);
  a04=arg[0]? arg[0][3] : 0;
  a05=(2.*a04);
  a06=arg[0]? arg[0][4] : 0;
  a07=(a05*a06);
  a03=(a03+a07);
  a08=arg[1]? arg[1][3] : 0;
  a09=(a03*a08);
  a10=1.;
  a11=-2.;
  a12=casadi_sq(a04);
  a12=(a11*a12);
  a12=(a10+a12);
  a13=casadi_sq(a02);
  a13=(a11*a13);
  a14=(a12+a13);
  a15=arg[1]? arg[1][4] : 0;
  a16=(a14*a15);
  a09=(a09+a16);
  a00=(a11*a00);
  a16=(a00*a04);
  a17=(2.*a06);
  a17=(a17*a02);
  a16=(a16+a17);
  a18=arg[1]? arg[1][5] : 0;
  a19=(a16*a18);
  a09=(a09+a19);
  a19=(a00*a06);
  a05=(a05*a02);
  a19=(a19+a05);
  a20=arg[1]? arg[1][0] : 0;
  a21=(a19*a20);
  a04=(a01*a04);
  a04=(a04+a17);
  a17=arg[1]? arg[1][1] : 0;
  a22=(a04*a17);
  a21=(a21+a22);
  a22=casadi_sq(a06);
  a11=(a11*a22);
  a12=(a12+a11);
  a22=arg[1]? arg[1][2] : 0;
  a23=(a12*a22);
  a21=(a21+a23);
  a23=(a09*a21);
  a24=(a19*a08);
  a25=(a04*a15);
  a24=(a24+a25);
  a25=(a12*a18);
  a24=(a24+a25);
  a25=(a03*a20);
  a26=(a14*a17);
  a25=(a25+a26);
  a26=(a16*a22);
  a25=(a25+a26);
  a26=(a24*a25);
  a23=(a23-a26);
  a26=arg[3]? arg[3][0] : 0;
  a27=(a23*a26);
  a28=arg[2]? arg[2][87] : 0;
  a29=(a03*a28);
  a30=arg[2]? arg[2][88] : 0;
  a31=(a14*a30);
  a29=(a29+a31);
  a31=arg[2]? arg[2][89] : 0;
  a32=(a16*a31);
  a29=(a29+a32);
  a10=(a10+a11);
  a10=(a10+a13);
  a08=(a10*a08);
  a00=(a00*a02);
  a00=(a00+a07);
  a15=(a00*a15);
  a08=(a08+a15);
  a01=(a01*a06);
  a01=(a01+a05);
  a18=(a01*a18);
  a08=(a08+a18);
  a18=(a29*a08);
  a05=(a10*a28);
  a06=(a00*a30);
  a05=(a05+a06);
  a06=(a01*a31);
  a05=(a05+a06);
  a06=(a05*a09);
  a18=(a18-a06);
  a06=(a09*a18);
  a23=(a23+a06);
  a05=(a05*a24);
  a28=(a19*a28);
  a30=(a04*a30);
  a28=(a28+a30);
  a31=(a12*a31);
  a28=(a28+a31);
  a31=(a28*a08);
  a05=(a05-a31);
  a31=(a24*a05);
  a23=(a23-a31);
  a31=arg[3]? arg[3][1] : 0;
  a30=(a23*a31);
  a27=(a27+a30);
  a30=arg[1]? arg[1][6] : 0;
  a06=arg[2]? arg[2][75] : 0;
  a15=(a06*a10);
  a07=arg[2]? arg[2][76] : 0;
  a02=(a07*a00);
  a15=(a15+a02);
  a02=arg[2]? arg[2][77] : 0;
  a13=(a02*a01);
  a15=(a15+a13);
  a13=(a15*a24);
  a11=(a06*a19);
  a32=(a07*a04);
  a11=(a11+a32);
  a32=(a02*a12);
  a11=(a11+a32);
  a32=(a11*a08);
  a13=(a13-a32);
  a13=(a30*a13);
  a32=arg[2]? arg[2][92] : 0;
  a33=(a11*a32);
  a34=arg[2]? arg[2][69] : 0;
  a35=(a34*a19);
  a36=arg[2]? arg[2][70] : 0;
  a37=(a36*a04);
  a35=(a35+a37);
  a37=arg[2]? arg[2][71] : 0;
  a38=(a37*a12);
  a35=(a35+a38);
  a38=arg[0]? arg[0][7] : 0;
  a39=cos(a38);
  a40=(a35*a39);
  a41=arg[2]? arg[2][72] : 0;
  a42=(a41*a19);
  a43=arg[2]? arg[2][73] : 0;
  a44=(a43*a04);
  a42=(a42+a44);
  a44=arg[2]? arg[2][74] : 0;
  a45=(a44*a12);
  a42=(a42+a45);
  a38=sin(a38);
  a45=(a42*a38);
  a40=(a40+a45);
  a45=arg[2]? arg[2][90] : 0;
  a46=(a40*a45);
  a33=(a33+a46);
  a42=(a42*a39);
  a35=(a35*a38);
  a42=(a42-a35);
  a35=arg[2]? arg[2][91] : 0;
  a46=(a42*a35);
  a33=(a33+a46);
  a46=(a13*a33);
  a23=(a23+a46);
  a06=(a06*a03);
  a07=(a07*a14);
  a06=(a06+a07);
  a02=(a02*a16);
  a06=(a06+a02);
  a02=(a06*a30);
  a02=(a09+a02);
  a07=(a06*a32);
  a46=(a34*a03);
  a47=(a36*a14);
  a46=(a46+a47);
  a47=(a37*a16);
  a46=(a46+a47);
  a47=(a46*a39);
  a48=(a41*a03);
  a49=(a43*a14);
  a48=(a48+a49);
  a49=(a44*a16);
  a48=(a48+a49);
  a49=(a48*a38);
  a47=(a47+a49);
  a49=(a47*a45);
  a07=(a07+a49);
  a48=(a48*a39);
  a46=(a46*a38);
  a48=(a48-a46);
  a46=(a48*a35);
  a07=(a07+a46);
  a46=(a15*a30);
  a46=(a08+a46);
  a49=(a07*a46);
  a32=(a15*a32);
  a34=(a34*a10);
  a36=(a36*a00);
  a34=(a34+a36);
  a37=(a37*a01);
  a34=(a34+a37);
  a37=(a34*a39);
  a41=(a41*a10);
  a43=(a43*a00);
  a41=(a41+a43);
  a44=(a44*a01);
  a41=(a41+a44);
  a44=(a41*a38);
  a37=(a37+a44);
  a45=(a37*a45);
  a32=(a32+a45);
  a41=(a41*a39);
  a34=(a34*a38);
  a41=(a41-a34);
  a35=(a41*a35);
  a32=(a32+a35);
  a35=(a32*a02);
  a49=(a49-a35);
  a35=(a02*a49);
  a23=(a23+a35);
  a35=(a06*a08);
  a34=(a15*a09);
  a35=(a35-a34);
  a35=(a30*a35);
  a34=(a35*a07);
  a23=(a23-a34);
  a34=(a11*a30);
  a34=(a24+a34);
  a38=(a32*a34);
  a39=(a33*a46);
  a38=(a38-a39);
  a39=(a34*a38);
  a23=(a23-a39);
  a39=arg[3]? arg[3][2] : 0;
  a23=(a23*a39);
  a27=(a27+a23);
  a23=(a13*a31);
  a45=arg[1]? arg[1][7] : 0;
  a44=arg[2]? arg[2][86] : 0;
  a43=(a15*a44);
  a36=arg[2]? arg[2][84] : 0;
  a50=(a36*a37);
  a43=(a43+a50);
  a50=arg[2]? arg[2][85] : 0;
  a51=(a50*a41);
  a43=(a43+a51);
  a51=(a43*a34);
  a52=(a11*a44);
  a53=(a36*a40);
  a52=(a52+a53);
  a53=(a50*a42);
  a52=(a52+a53);
  a53=(a52*a46);
  a51=(a51-a53);
  a51=(a45*a51);
  a51=(a13+a51);
  a51=(a51*a39);
  a23=(a23+a51);
  a51=(a40*a31);
  a53=arg[2]? arg[2][80] : 0;
  a54=(a11*a53);
  a55=arg[2]? arg[2][78] : 0;
  a56=(a55*a40);
  a54=(a54+a56);
  a56=arg[2]? arg[2][79] : 0;
  a57=(a56*a42);
  a54=(a54+a57);
  a57=arg[0]? arg[0][8] : 0;
  a58=cos(a57);
  a59=(a54*a58);
  a60=arg[2]? arg[2][83] : 0;
  a61=(a11*a60);
  a62=arg[2]? arg[2][81] : 0;
  a40=(a62*a40);
  a61=(a61+a40);
  a40=arg[2]? arg[2][82] : 0;
  a63=(a40*a42);
  a61=(a61+a63);
  a57=sin(a57);
  a63=(a61*a57);
  a59=(a59+a63);
  a59=(a59*a39);
  a51=(a51+a59);
  a19=(a19*a26);
  a51=(a51+a19);
  a19=arg[2]? arg[2][51] : 0;
  a19=(a19*a31);
  a19=(a26+a19);
  a59=arg[2]? arg[2][60] : 0;
  a59=(a59*a39);
  a19=(a19+a59);
  a59=arg[4]? arg[4][0] : 0;
  a19=(a19*a59);
  a63=arg[2]? arg[2][52] : 0;
  a63=(a63*a31);
  a64=arg[2]? arg[2][61] : 0;
  a64=(a64*a39);
  a63=(a63+a64);
  a64=arg[4]? arg[4][1] : 0;
  a63=(a63*a64);
  a19=(a19+a63);
  a63=arg[2]? arg[2][53] : 0;
  a63=(a63*a31);
  a65=arg[2]? arg[2][62] : 0;
  a65=(a65*a39);
  a63=(a63+a65);
  a65=arg[4]? arg[4][2] : 0;
  a63=(a63*a65);
  a19=(a19+a63);
  a51=(a51*a19);
  a42=(a42*a31);
  a61=(a61*a58);
  a54=(a54*a57);
  a61=(a61-a54);
  a61=(a61*a39);
  a42=(a42+a61);
  a04=(a04*a26);
  a42=(a42+a04);
  a04=arg[2]? arg[2][54] : 0;
  a04=(a04*a31);
  a61=arg[2]? arg[2][63] : 0;
  a61=(a61*a39);
  a04=(a04+a61);
  a04=(a04*a59);
  a61=arg[2]? arg[2][55] : 0;
  a61=(a61*a31);
  a61=(a26+a61);
  a54=arg[2]? arg[2][64] : 0;
  a54=(a54*a39);
  a61=(a61+a54);
  a61=(a61*a64);
  a04=(a04+a61);
  a61=arg[2]? arg[2][56] : 0;
  a61=(a61*a31);
  a54=arg[2]? arg[2][65] : 0;
  a54=(a54*a39);
  a61=(a61+a54);
  a61=(a61*a65);
  a04=(a04+a61);
  a42=(a42*a04);
  a51=(a51+a42);
  a42=(a11*a31);
  a61=(a52*a39);
  a42=(a42+a61);
  a12=(a12*a26);
  a42=(a42+a12);
  a12=arg[2]? arg[2][57] : 0;
  a12=(a12*a31);
  a61=arg[2]? arg[2][66] : 0;
  a61=(a61*a39);
  a12=(a12+a61);
  a12=(a12*a59);
  a59=arg[2]? arg[2][58] : 0;
  a59=(a59*a31);
  a61=arg[2]? arg[2][67] : 0;
  a61=(a61*a39);
  a59=(a59+a61);
  a59=(a59*a64);
  a12=(a12+a59);
  a59=arg[2]? arg[2][59] : 0;
  a59=(a59*a31);
  a59=(a26+a59);
  a64=arg[2]? arg[2][68] : 0;
  a64=(a64*a39);
  a59=(a59+a64);
  a59=(a59*a65);
  a12=(a12+a59);
  a42=(a42*a12);
  a51=(a51+a42);
  a42=(a23*a51);
  a27=(a27+a42);
  a42=(a09*a26);
  a59=(a02*a31);
  a42=(a42+a59);
  a44=(a06*a44);
  a36=(a36*a47);
  a44=(a44+a36);
  a50=(a50*a48);
  a44=(a44+a50);
  a50=(a44*a45);
  a50=(a02+a50);
  a50=(a50*a39);
  a42=(a42+a50);
  a50=(a47*a31);
  a36=(a06*a53);
  a59=(a55*a47);
  a36=(a36+a59);
  a59=(a56*a48);
  a36=(a36+a59);
  a59=(a36*a58);
  a65=(a06*a60);
  a47=(a62*a47);
  a65=(a65+a47);
  a47=(a40*a48);
  a65=(a65+a47);
  a47=(a65*a57);
  a59=(a59+a47);
  a59=(a59*a39);
  a50=(a50+a59);
  a03=(a03*a26);
  a50=(a50+a03);
  a50=(a50*a19);
  a48=(a48*a31);
  a65=(a65*a58);
  a36=(a36*a57);
  a65=(a65-a36);
  a65=(a65*a39);
  a48=(a48+a65);
  a14=(a14*a26);
  a48=(a48+a14);
  a48=(a48*a04);
  a50=(a50+a48);
  a48=(a06*a31);
  a14=(a44*a39);
  a48=(a48+a14);
  a16=(a16*a26);
  a48=(a48+a16);
  a48=(a48*a12);
  a50=(a50+a48);
  a48=(a08*a26);
  a16=(a46*a31);
  a48=(a48+a16);
  a16=(a43*a45);
  a16=(a46+a16);
  a16=(a16*a39);
  a48=(a48+a16);
  a16=(a50*a48);
  a14=(a37*a31);
  a53=(a15*a53);
  a55=(a55*a37);
  a53=(a53+a55);
  a56=(a56*a41);
  a53=(a53+a56);
  a56=(a53*a58);
  a60=(a15*a60);
  a62=(a62*a37);
  a60=(a60+a62);
  a40=(a40*a41);
  a60=(a60+a40);
  a40=(a60*a57);
  a56=(a56+a40);
  a56=(a56*a39);
  a14=(a14+a56);
  a56=(a10*a26);
  a14=(a14+a56);
  a14=(a14*a19);
  a41=(a41*a31);
  a60=(a60*a58);
  a53=(a53*a57);
  a60=(a60-a53);
  a60=(a60*a39);
  a41=(a41+a60);
  a60=(a00*a26);
  a41=(a41+a60);
  a41=(a41*a04);
  a14=(a14+a41);
  a15=(a15*a31);
  a41=(a43*a39);
  a15=(a15+a41);
  a41=(a01*a26);
  a15=(a15+a41);
  a15=(a15*a12);
  a14=(a14+a15);
  a15=(a14*a42);
  a16=(a16-a15);
  a15=(a42*a16);
  a27=(a27+a15);
  a15=(a35*a31);
  a12=(a44*a46);
  a43=(a43*a02);
  a12=(a12-a43);
  a12=(a45*a12);
  a12=(a35+a12);
  a12=(a12*a39);
  a15=(a15+a12);
  a12=(a15*a50);
  a27=(a27-a12);
  a12=(a24*a26);
  a43=(a34*a31);
  a12=(a12+a43);
  a43=(a52*a45);
  a43=(a34+a43);
  a43=(a43*a39);
  a12=(a12+a43);
  a43=(a14*a12);
  a41=(a51*a48);
  a43=(a43-a41);
  a41=(a12*a43);
  a27=(a27-a41);
  if (res[0]!=0) res[0][0]=a27;
  a10=(a10*a20);
  a00=(a00*a17);
  a10=(a10+a00);
  a01=(a01*a22);
  a10=(a10+a01);
  a01=(a24*a10);
  a21=(a08*a21);
  a01=(a01-a21);
  a21=(a01*a26);
  a28=(a28*a09);
  a29=(a29*a24);
  a28=(a28-a29);
  a29=(a24*a28);
  a01=(a01+a29);
  a18=(a08*a18);
  a01=(a01-a18);
  a18=(a01*a31);
  a21=(a21+a18);
  a35=(a35*a32);
  a01=(a01+a35);
  a35=(a33*a02);
  a18=(a07*a34);
  a35=(a35-a18);
  a18=(a34*a35);
  a01=(a01+a18);
  a11=(a11*a09);
  a06=(a06*a24);
  a11=(a11-a06);
  a30=(a30*a11);
  a33=(a30*a33);
  a01=(a01-a33);
  a49=(a46*a49);
  a01=(a01-a49);
  a01=(a01*a39);
  a21=(a21+a01);
  a15=(a15*a14);
  a21=(a21+a15);
  a15=(a51*a42);
  a01=(a50*a12);
  a15=(a15-a01);
  a12=(a12*a15);
  a21=(a21+a12);
  a12=(a30*a31);
  a52=(a52*a02);
  a44=(a44*a34);
  a52=(a52-a44);
  a45=(a45*a52);
  a45=(a30+a45);
  a45=(a45*a39);
  a12=(a12+a45);
  a51=(a12*a51);
  a21=(a21-a51);
  a16=(a48*a16);
  a21=(a21-a16);
  if (res[0]!=0) res[0][1]=a21;
  a25=(a08*a25);
  a10=(a09*a10);
  a25=(a25-a10);
  a26=(a25*a26);
  a08=(a08*a05);
  a25=(a25+a08);
  a09=(a09*a28);
  a25=(a25-a09);
  a31=(a25*a31);
  a26=(a26+a31);
  a30=(a30*a07);
  a25=(a25+a30);
  a46=(a46*a38);
  a25=(a25+a46);
  a13=(a13*a32);
  a25=(a25-a13);
  a02=(a02*a35);
  a25=(a25-a02);
  a25=(a25*a39);
  a26=(a26+a25);
  a12=(a12*a50);
  a26=(a26+a12);
  a48=(a48*a43);
  a26=(a26+a48);
  a23=(a23*a14);
  a26=(a26-a23);
  a42=(a42*a15);
  a26=(a26-a42);
  if (res[0]!=0) res[0][2]=a26;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_bias_acceleration(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_bias_acceleration_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_point_bias_acceleration_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_point_bias_acceleration_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_point_bias_acceleration_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_point_bias_acceleration_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_point_bias_acceleration_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_point_bias_acceleration_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_point_bias_acceleration_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "link";
    case 4: return "point";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_point_bias_acceleration_name_out(casadi_int i) {
  switch (i) {
    case 0: return "bias";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_point_bias_acceleration_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_point_bias_acceleration_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_bias_acceleration_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_bias_acceleration_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5*sizeof(const casadi_real*);
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

/* snakecg_sp2_point_bias_acceleration_sincos: 564 CasADi instructions, printed one per line */
static void snakecg_sp2_point_bias_acceleration_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    const casadi_real* restrict arg6,
    casadi_real* restrict res0) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58, w59;
  casadi_real w60, w61, w62, w63, w64, w65;
  w0 = arg0[6];
  w1 = w0 + w0;
  w2 = arg0[5];
  w3 = w1 * w2;
  w4 = arg0[3];
  w5 = w4 + w4;
  w6 = arg0[4];
  w7 = w5 * w6;
  w3 = w3 + w7;
  w8 = arg1[3];
  w9 = w3 * w8;
  w10 = 1.0;
  w11 = (-2.0);
  w12 = w4 * w4;
  w12 = w11 * w12;
  w12 = w10 + w12;
  w13 = w2 * w2;
  w13 = w11 * w13;
  w14 = w12 + w13;
  w15 = arg1[4];
  w16 = w14 * w15;
  w9 = w9 + w16;
  w0 = w11 * w0;
  w16 = w0 * w4;
  w17 = w6 + w6;
  w17 = w17 * w2;
  w16 = w16 + w17;
  w18 = arg1[5];
  w19 = w16 * w18;
  w9 = w9 + w19;
  w19 = w0 * w6;
  w5 = w5 * w2;
  w19 = w19 + w5;
  w20 = arg1[0];
  w21 = w19 * w20;
  w4 = w1 * w4;
  w4 = w4 + w17;
  w17 = arg1[1];
  w22 = w4 * w17;
  w21 = w21 + w22;
  w22 = w6 * w6;
  w11 = w11 * w22;
  w12 = w12 + w11;
  w22 = arg1[2];
  w23 = w12 * w22;
  w21 = w21 + w23;
  w23 = w9 * w21;
  w24 = w19 * w8;
  w25 = w4 * w15;
  w24 = w24 + w25;
  w25 = w12 * w18;
  w24 = w24 + w25;
  w25 = w3 * w20;
  w26 = w14 * w17;
  w25 = w25 + w26;
  w26 = w16 * w22;
  w25 = w25 + w26;
  w26 = w24 * w25;
  w23 = w23 - w26;
  w26 = arg3[0];
  w27 = w23 * w26;
  w28 = arg2[87];
  w29 = w3 * w28;
  w30 = arg2[88];
  w31 = w14 * w30;
  w29 = w29 + w31;
  w31 = arg2[89];
  w32 = w16 * w31;
  w29 = w29 + w32;
  w10 = w10 + w11;
  w10 = w10 + w13;
  w8 = w10 * w8;
  w0 = w0 * w2;
  w0 = w0 + w7;
  w15 = w0 * w15;
  w8 = w8 + w15;
  w1 = w1 * w6;
  w1 = w1 + w5;
  w18 = w1 * w18;
  w8 = w8 + w18;
  w18 = w29 * w8;
  w5 = w10 * w28;
  w6 = w0 * w30;
  w5 = w5 + w6;
  w6 = w1 * w31;
  w5 = w5 + w6;
  w6 = w5 * w9;
  w18 = w18 - w6;
  w6 = w9 * w18;
  w23 = w23 + w6;
  w5 = w5 * w24;
  w28 = w19 * w28;
  w30 = w4 * w30;
  w28 = w28 + w30;
  w31 = w12 * w31;
  w28 = w28 + w31;
  w31 = w28 * w8;
  w5 = w5 - w31;
  w31 = w24 * w5;
  w23 = w23 - w31;
  w31 = arg3[1];
  w30 = w23 * w31;
  w27 = w27 + w30;
  w30 = arg1[6];
  w6 = arg2[75];
  w15 = w6 * w10;
  w7 = arg2[76];
  w2 = w7 * w0;
  w15 = w15 + w2;
  w2 = arg2[77];
  w13 = w2 * w1;
  w15 = w15 + w13;
  w13 = w15 * w24;
  w11 = w6 * w19;
  w32 = w7 * w4;
  w11 = w11 + w32;
  w32 = w2 * w12;
  w11 = w11 + w32;
  w32 = w11 * w8;
  w13 = w13 - w32;
  w13 = w30 * w13;
  w32 = arg2[92];
  w33 = w11 * w32;
  w34 = arg2[69];
  w35 = w34 * w19;
  w36 = arg2[70];
  w37 = w36 * w4;
  w35 = w35 + w37;
  w37 = arg2[71];
  w38 = w37 * w12;
  w35 = w35 + w38;
  w38 = arg5[0];
  w39 = w35 * w38;
  w40 = arg2[72];
  w41 = w40 * w19;
  w42 = arg2[73];
  w43 = w42 * w4;
  w41 = w41 + w43;
  w43 = arg2[74];
  w44 = w43 * w12;
  w41 = w41 + w44;
  w44 = arg6[0];
  w45 = w41 * w44;
  w39 = w39 + w45;
  w45 = arg2[90];
  w46 = w39 * w45;
  w33 = w33 + w46;
  w41 = w41 * w38;
  w35 = w35 * w44;
  w41 = w41 - w35;
  w35 = arg2[91];
  w46 = w41 * w35;
  w33 = w33 + w46;
  w46 = w13 * w33;
  w23 = w23 + w46;
  w6 = w6 * w3;
  w7 = w7 * w14;
  w6 = w6 + w7;
  w2 = w2 * w16;
  w6 = w6 + w2;
  w2 = w6 * w30;
  w2 = w9 + w2;
  w7 = w6 * w32;
  w46 = w34 * w3;
  w47 = w36 * w14;
  w46 = w46 + w47;
  w47 = w37 * w16;
  w46 = w46 + w47;
  w47 = w46 * w38;
  w48 = w40 * w3;
  w49 = w42 * w14;
  w48 = w48 + w49;
  w49 = w43 * w16;
  w48 = w48 + w49;
  w49 = w48 * w44;
  w47 = w47 + w49;
  w49 = w47 * w45;
  w7 = w7 + w49;
  w48 = w48 * w38;
  w46 = w46 * w44;
  w48 = w48 - w46;
  w46 = w48 * w35;
  w7 = w7 + w46;
  w46 = w15 * w30;
  w46 = w8 + w46;
  w49 = w7 * w46;
  w32 = w15 * w32;
  w34 = w34 * w10;
  w36 = w36 * w0;
  w34 = w34 + w36;
  w37 = w37 * w1;
  w34 = w34 + w37;
  w37 = w34 * w38;
  w40 = w40 * w10;
  w42 = w42 * w0;
  w40 = w40 + w42;
  w43 = w43 * w1;
  w40 = w40 + w43;
  w43 = w40 * w44;
  w37 = w37 + w43;
  w45 = w37 * w45;
  w32 = w32 + w45;
  w40 = w40 * w38;
  w34 = w34 * w44;
  w40 = w40 - w34;
  w35 = w40 * w35;
  w32 = w32 + w35;
  w35 = w32 * w2;
  w49 = w49 - w35;
  w35 = w2 * w49;
  w23 = w23 + w35;
  w35 = w6 * w8;
  w34 = w15 * w9;
  w35 = w35 - w34;
  w35 = w30 * w35;
  w34 = w35 * w7;
  w23 = w23 - w34;
  w34 = w11 * w30;
  w34 = w24 + w34;
  w44 = w32 * w34;
  w38 = w33 * w46;
  w44 = w44 - w38;
  w38 = w34 * w44;
  w23 = w23 - w38;
  w38 = arg3[2];
  w23 = w23 * w38;
  w27 = w27 + w23;
  w23 = w13 * w31;
  w45 = arg1[7];
  w43 = arg2[86];
  w42 = w15 * w43;
  w36 = arg2[84];
  w50 = w36 * w37;
  w42 = w42 + w50;
  w50 = arg2[85];
  w51 = w50 * w40;
  w42 = w42 + w51;
  w51 = w42 * w34;
  w52 = w11 * w43;
  w53 = w36 * w39;
  w52 = w52 + w53;
  w53 = w50 * w41;
  w52 = w52 + w53;
  w53 = w52 * w46;
  w51 = w51 - w53;
  w51 = w45 * w51;
  w51 = w13 + w51;
  w51 = w51 * w38;
  w23 = w23 + w51;
  w51 = w39 * w31;
  w53 = arg2[80];
  w54 = w11 * w53;
  w55 = arg2[78];
  w56 = w55 * w39;
  w54 = w54 + w56;
  w56 = arg2[79];
  w57 = w56 * w41;
  w54 = w54 + w57;
  w57 = arg5[1];
  w58 = w54 * w57;
  w59 = arg2[83];
  w60 = w11 * w59;
  w61 = arg2[81];
  w39 = w61 * w39;
  w60 = w60 + w39;
  w39 = arg2[82];
  w62 = w39 * w41;
  w60 = w60 + w62;
  w62 = arg6[1];
  w63 = w60 * w62;
  w58 = w58 + w63;
  w58 = w58 * w38;
  w51 = w51 + w58;
  w19 = w19 * w26;
  w51 = w51 + w19;
  w19 = arg2[51];
  w19 = w19 * w31;
  w19 = w26 + w19;
  w58 = arg2[60];
  w58 = w58 * w38;
  w19 = w19 + w58;
  w58 = arg4[0];
  w19 = w19 * w58;
  w63 = arg2[52];
  w63 = w63 * w31;
  w64 = arg2[61];
  w64 = w64 * w38;
  w63 = w63 + w64;
  w64 = arg4[1];
  w63 = w63 * w64;
  w19 = w19 + w63;
  w63 = arg2[53];
  w63 = w63 * w31;
  w65 = arg2[62];
  w65 = w65 * w38;
  w63 = w63 + w65;
  w65 = arg4[2];
  w63 = w63 * w65;
  w19 = w19 + w63;
  w51 = w51 * w19;
  w41 = w41 * w31;
  w60 = w60 * w57;
  w54 = w54 * w62;
  w60 = w60 - w54;
  w60 = w60 * w38;
  w41 = w41 + w60;
  w4 = w4 * w26;
  w41 = w41 + w4;
  w4 = arg2[54];
  w4 = w4 * w31;
  w60 = arg2[63];
  w60 = w60 * w38;
  w4 = w4 + w60;
  w4 = w4 * w58;
  w60 = arg2[55];
  w60 = w60 * w31;
  w60 = w26 + w60;
  w54 = arg2[64];
  w54 = w54 * w38;
  w60 = w60 + w54;
  w60 = w60 * w64;
  w4 = w4 + w60;
  w60 = arg2[56];
  w60 = w60 * w31;
  w54 = arg2[65];
  w54 = w54 * w38;
  w60 = w60 + w54;
  w60 = w60 * w65;
  w4 = w4 + w60;
  w41 = w41 * w4;
  w51 = w51 + w41;
  w41 = w11 * w31;
  w60 = w52 * w38;
  w41 = w41 + w60;
  w12 = w12 * w26;
  w41 = w41 + w12;
  w12 = arg2[57];
  w12 = w12 * w31;
  w60 = arg2[66];
  w60 = w60 * w38;
  w12 = w12 + w60;
  w12 = w12 * w58;
  w58 = arg2[58];
  w58 = w58 * w31;
  w60 = arg2[67];
  w60 = w60 * w38;
  w58 = w58 + w60;
  w58 = w58 * w64;
  w12 = w12 + w58;
  w58 = arg2[59];
  w58 = w58 * w31;
  w58 = w26 + w58;
  w64 = arg2[68];
  w64 = w64 * w38;
  w58 = w58 + w64;
  w58 = w58 * w65;
  w12 = w12 + w58;
  w41 = w41 * w12;
  w51 = w51 + w41;
  w41 = w23 * w51;
  w27 = w27 + w41;
  w41 = w9 * w26;
  w58 = w2 * w31;
  w41 = w41 + w58;
  w43 = w6 * w43;
  w36 = w36 * w47;
  w43 = w43 + w36;
  w50 = w50 * w48;
  w43 = w43 + w50;
  w50 = w43 * w45;
  w50 = w2 + w50;
  w50 = w50 * w38;
  w41 = w41 + w50;
  w50 = w47 * w31;
  w36 = w6 * w53;
  w58 = w55 * w47;
  w36 = w36 + w58;
  w58 = w56 * w48;
  w36 = w36 + w58;
  w58 = w36 * w57;
  w65 = w6 * w59;
  w47 = w61 * w47;
  w65 = w65 + w47;
  w47 = w39 * w48;
  w65 = w65 + w47;
  w47 = w65 * w62;
  w58 = w58 + w47;
  w58 = w58 * w38;
  w50 = w50 + w58;
  w3 = w3 * w26;
  w50 = w50 + w3;
  w50 = w50 * w19;
  w48 = w48 * w31;
  w65 = w65 * w57;
  w36 = w36 * w62;
  w65 = w65 - w36;
  w65 = w65 * w38;
  w48 = w48 + w65;
  w14 = w14 * w26;
  w48 = w48 + w14;
  w48 = w48 * w4;
  w50 = w50 + w48;
  w48 = w6 * w31;
  w14 = w43 * w38;
  w48 = w48 + w14;
  w16 = w16 * w26;
  w48 = w48 + w16;
  w48 = w48 * w12;
  w50 = w50 + w48;
  w48 = w8 * w26;
  w16 = w46 * w31;
  w48 = w48 + w16;
  w16 = w42 * w45;
  w16 = w46 + w16;
  w16 = w16 * w38;
  w48 = w48 + w16;
  w16 = w50 * w48;
  w14 = w37 * w31;
  w53 = w15 * w53;
  w55 = w55 * w37;
  w53 = w53 + w55;
  w56 = w56 * w40;
  w53 = w53 + w56;
  w56 = w53 * w57;
  w59 = w15 * w59;
  w61 = w61 * w37;
  w59 = w59 + w61;
  w39 = w39 * w40;
  w59 = w59 + w39;
  w39 = w59 * w62;
  w56 = w56 + w39;
  w56 = w56 * w38;
  w14 = w14 + w56;
  w56 = w10 * w26;
  w14 = w14 + w56;
  w14 = w14 * w19;
  w40 = w40 * w31;
  w59 = w59 * w57;
  w53 = w53 * w62;
  w59 = w59 - w53;
  w59 = w59 * w38;
  w40 = w40 + w59;
  w59 = w0 * w26;
  w40 = w40 + w59;
  w40 = w40 * w4;
  w14 = w14 + w40;
  w15 = w15 * w31;
  w40 = w42 * w38;
  w15 = w15 + w40;
  w40 = w1 * w26;
  w15 = w15 + w40;
  w15 = w15 * w12;
  w14 = w14 + w15;
  w15 = w14 * w41;
  w16 = w16 - w15;
  w15 = w41 * w16;
  w27 = w27 + w15;
  w15 = w35 * w31;
  w12 = w43 * w46;
  w42 = w42 * w2;
  w12 = w12 - w42;
  w12 = w45 * w12;
  w12 = w35 + w12;
  w12 = w12 * w38;
  w15 = w15 + w12;
  w12 = w15 * w50;
  w27 = w27 - w12;
  w12 = w24 * w26;
  w42 = w34 * w31;
  w12 = w12 + w42;
  w42 = w52 * w45;
  w42 = w34 + w42;
  w42 = w42 * w38;
  w12 = w12 + w42;
  w42 = w14 * w12;
  w40 = w51 * w48;
  w42 = w42 - w40;
  w40 = w12 * w42;
  w27 = w27 - w40;
  res0[0] = w27;
  w10 = w10 * w20;
  w0 = w0 * w17;
  w10 = w10 + w0;
  w1 = w1 * w22;
  w10 = w10 + w1;
  w1 = w24 * w10;
  w21 = w8 * w21;
  w1 = w1 - w21;
  w21 = w1 * w26;
  w28 = w28 * w9;
  w29 = w29 * w24;
  w28 = w28 - w29;
  w29 = w24 * w28;
  w1 = w1 + w29;
  w18 = w8 * w18;
  w1 = w1 - w18;
  w18 = w1 * w31;
  w21 = w21 + w18;
  w35 = w35 * w32;
  w1 = w1 + w35;
  w35 = w33 * w2;
  w18 = w7 * w34;
  w35 = w35 - w18;
  w18 = w34 * w35;
  w1 = w1 + w18;
  w11 = w11 * w9;
  w6 = w6 * w24;
  w11 = w11 - w6;
  w30 = w30 * w11;
  w33 = w30 * w33;
  w1 = w1 - w33;
  w49 = w46 * w49;
  w1 = w1 - w49;
  w1 = w1 * w38;
  w21 = w21 + w1;
  w15 = w15 * w14;
  w21 = w21 + w15;
  w15 = w51 * w41;
  w1 = w50 * w12;
  w15 = w15 - w1;
  w12 = w12 * w15;
  w21 = w21 + w12;
  w12 = w30 * w31;
  w52 = w52 * w2;
  w43 = w43 * w34;
  w52 = w52 - w43;
  w45 = w45 * w52;
  w45 = w30 + w45;
  w45 = w45 * w38;
  w12 = w12 + w45;
  w51 = w12 * w51;
  w21 = w21 - w51;
  w16 = w48 * w16;
  w21 = w21 - w16;
  res0[1] = w21;
  w25 = w8 * w25;
  w10 = w9 * w10;
  w25 = w25 - w10;
  w26 = w25 * w26;
  w8 = w8 * w5;
  w25 = w25 + w8;
  w9 = w9 * w28;
  w25 = w25 - w9;
  w31 = w25 * w31;
  w26 = w26 + w31;
  w30 = w30 * w7;
  w25 = w25 + w30;
  w46 = w46 * w44;
  w25 = w25 + w46;
  w13 = w13 * w32;
  w25 = w25 - w13;
  w2 = w2 * w35;
  w25 = w25 - w2;
  w25 = w25 * w38;
  w26 = w26 + w25;
  w12 = w12 * w50;
  w26 = w26 + w12;
  w48 = w48 * w42;
  w26 = w26 + w48;
  w23 = w23 * w14;
  w26 = w26 - w23;
  w41 = w41 * w15;
  w26 = w26 - w41;
  res0[2] = w26;
}


CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_point_bias_acceleration(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[5];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 67);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 5; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && arg[4] && res[0]) {
    /* cos and sin of q[7..8] of 16 samples at a time, then snakecg_sp2_point_bias_acceleration_sincos
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
        snakecg_sp2_point_bias_acceleration_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], arg[4] + (i0 + i) * stride[4], ca + i * na, sa + i * na, res[0] + (i0 + i) * 3);
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
      r[0] = res[0] + i * 3;
      if (snakecg_sp2_point_bias_acceleration(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
