/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for point_jacobian() of
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
  #define CASADI_PREFIX(ID) snakecg_sp2_point_jacobian_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp2_point_jacobian_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_point_jacobian_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_point_jacobian_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {120, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {3, 8, 1};

/* snakecg_sp2_point_jacobian:(q[9],K[120],link[3],point[3])->(position[3],J[3x8]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62;
  a00=arg[1]? arg[1][69] : 0;
  a01=1.;
  a02=-2.;
  a03=arg[0]? arg[0][4] : 0;
  a04=casadi_sq(a03);
  a04=(a02*a04);
  a05=(a01+a04);
  a06=arg[0]? arg[0][5] : 0;
  a07=casadi_sq(a06);
  a07=(a02*a07);
  a05=(a05+a07);
  a08=(a00*a05);
  a09=arg[1]? arg[1][70] : 0;
  a10=arg[0]? arg[0][6] : 0;
  a11=(a02*a10);
  a12=(a11*a06);
  a13=arg[0]? arg[0][3] : 0;
  a14=(2.*a13);
  a15=(a14*a03);
  a12=(a12+a15);
  a16=(a09*a12);
  a08=(a08+a16);
  a16=arg[1]? arg[1][71] : 0;
  a10=(2.*a10);
  a17=(a10*a03);
  a14=(a14*a06);
  a17=(a17+a14);
  a18=(a16*a17);
  a08=(a08+a18);
  a18=arg[0]? arg[0][7] : 0;
  a19=cos(a18);
  a20=(a08*a19);
  a21=arg[1]? arg[1][72] : 0;
  a22=(a21*a05);
  a23=arg[1]? arg[1][73] : 0;
  a24=(a23*a12);
  a22=(a22+a24);
  a24=arg[1]? arg[1][74] : 0;
  a25=(a24*a17);
  a22=(a22+a25);
  a18=sin(a18);
  a25=(a22*a18);
  a20=(a20+a25);
  a25=arg[2]? arg[2][1] : 0;
  a26=(a20*a25);
  a27=arg[1]? arg[1][75] : 0;
  a28=(a27*a05);
  a29=arg[1]? arg[1][76] : 0;
  a30=(a29*a12);
  a28=(a28+a30);
  a30=arg[1]? arg[1][77] : 0;
  a31=(a30*a17);
  a28=(a28+a31);
  a31=arg[1]? arg[1][80] : 0;
  a32=(a28*a31);
  a33=arg[1]? arg[1][78] : 0;
  a34=(a33*a20);
  a32=(a32+a34);
  a34=arg[1]? arg[1][79] : 0;
  a22=(a22*a19);
  a08=(a08*a18);
  a22=(a22-a08);
  a08=(a34*a22);
  a32=(a32+a08);
  a08=arg[0]? arg[0][8] : 0;
  a35=cos(a08);
  a36=(a32*a35);
  a37=arg[1]? arg[1][83] : 0;
  a38=(a28*a37);
  a39=arg[1]? arg[1][81] : 0;
  a40=(a39*a20);
  a38=(a38+a40);
  a40=arg[1]? arg[1][82] : 0;
  a41=(a40*a22);
  a38=(a38+a41);
  a08=sin(a08);
  a41=(a38*a08);
  a36=(a36+a41);
  a41=arg[2]? arg[2][2] : 0;
  a36=(a36*a41);
  a26=(a26+a36);
  a36=arg[2]? arg[2][0] : 0;
  a42=(a05*a36);
  a26=(a26+a42);
  a42=arg[1]? arg[1][51] : 0;
  a42=(a42*a25);
  a42=(a36+a42);
  a43=arg[1]? arg[1][60] : 0;
  a43=(a43*a41);
  a42=(a42+a43);
  a43=arg[3]? arg[3][0] : 0;
  a42=(a42*a43);
  a44=arg[1]? arg[1][52] : 0;
  a44=(a44*a25);
  a45=arg[1]? arg[1][61] : 0;
  a45=(a45*a41);
  a44=(a44+a45);
  a45=arg[3]? arg[3][1] : 0;
  a44=(a44*a45);
  a42=(a42+a44);
  a44=arg[1]? arg[1][53] : 0;
  a44=(a44*a25);
  a46=arg[1]? arg[1][62] : 0;
  a46=(a46*a41);
  a44=(a44+a46);
  a46=arg[3]? arg[3][2] : 0;
  a44=(a44*a46);
  a42=(a42+a44);
  a26=(a26*a42);
  a44=(a22*a25);
  a38=(a38*a35);
  a32=(a32*a08);
  a38=(a38-a32);
  a38=(a38*a41);
  a44=(a44+a38);
  a38=(a12*a36);
  a44=(a44+a38);
  a38=arg[1]? arg[1][54] : 0;
  a38=(a38*a25);
  a32=arg[1]? arg[1][63] : 0;
  a32=(a32*a41);
  a38=(a38+a32);
  a38=(a38*a43);
  a32=arg[1]? arg[1][55] : 0;
  a32=(a32*a25);
  a32=(a36+a32);
  a47=arg[1]? arg[1][64] : 0;
  a47=(a47*a41);
  a32=(a32+a47);
  a32=(a32*a45);
  a38=(a38+a32);
  a32=arg[1]? arg[1][56] : 0;
  a32=(a32*a25);
  a47=arg[1]? arg[1][65] : 0;
  a47=(a47*a41);
  a32=(a32+a47);
  a32=(a32*a46);
  a38=(a38+a32);
  a44=(a44*a38);
  a26=(a26+a44);
  a44=(a28*a25);
  a32=arg[1]? arg[1][86] : 0;
  a47=(a28*a32);
  a48=arg[1]? arg[1][84] : 0;
  a49=(a48*a20);
  a47=(a47+a49);
  a49=arg[1]? arg[1][85] : 0;
  a50=(a49*a22);
  a47=(a47+a50);
  a50=(a47*a41);
  a44=(a44+a50);
  a50=(a17*a36);
  a44=(a44+a50);
  a50=arg[1]? arg[1][57] : 0;
  a50=(a50*a25);
  a51=arg[1]? arg[1][66] : 0;
  a51=(a51*a41);
  a50=(a50+a51);
  a50=(a50*a43);
  a43=arg[1]? arg[1][58] : 0;
  a43=(a43*a25);
  a51=arg[1]? arg[1][67] : 0;
  a51=(a51*a41);
  a43=(a43+a51);
  a43=(a43*a45);
  a50=(a50+a43);
  a43=arg[1]? arg[1][59] : 0;
  a43=(a43*a25);
  a43=(a36+a43);
  a45=arg[1]? arg[1][68] : 0;
  a45=(a45*a41);
  a43=(a43+a45);
  a43=(a43*a46);
  a50=(a50+a43);
  a44=(a44*a50);
  a26=(a26+a44);
  a44=arg[1]? arg[1][87] : 0;
  a43=(a05*a44);
  a46=arg[1]? arg[1][88] : 0;
  a45=(a12*a46);
  a43=(a43+a45);
  a45=arg[1]? arg[1][89] : 0;
  a51=(a17*a45);
  a43=(a43+a51);
  a51=arg[0]? arg[0][0] : 0;
  a43=(a43+a51);
  a52=(a43*a25);
  a53=arg[1]? arg[1][92] : 0;
  a54=(a28*a53);
  a55=arg[1]? arg[1][90] : 0;
  a20=(a20*a55);
  a54=(a54+a20);
  a20=arg[1]? arg[1][91] : 0;
  a22=(a22*a20);
  a54=(a54+a22);
  a54=(a54+a43);
  a22=(a54*a41);
  a52=(a52+a22);
  a22=(a36*a51);
  a52=(a52+a22);
  a26=(a26+a52);
  if (res[0]!=0) res[0][0]=a26;
  a52=(a10*a06);
  a52=(a52+a15);
  a15=(a00*a52);
  a22=casadi_sq(a13);
  a02=(a02*a22);
  a01=(a01+a02);
  a07=(a01+a07);
  a02=(a09*a07);
  a15=(a15+a02);
  a02=(a11*a13);
  a22=(2.*a03);
  a22=(a22*a06);
  a02=(a02+a22);
  a06=(a16*a02);
  a15=(a15+a06);
  a06=(a15*a19);
  a56=(a21*a52);
  a57=(a23*a07);
  a56=(a56+a57);
  a57=(a24*a02);
  a56=(a56+a57);
  a57=(a56*a18);
  a06=(a06+a57);
  a57=(a06*a25);
  a58=(a27*a52);
  a59=(a29*a07);
  a58=(a58+a59);
  a59=(a30*a02);
  a58=(a58+a59);
  a59=(a58*a31);
  a60=(a33*a06);
  a59=(a59+a60);
  a56=(a56*a19);
  a15=(a15*a18);
  a56=(a56-a15);
  a15=(a34*a56);
  a59=(a59+a15);
  a15=(a59*a35);
  a60=(a58*a37);
  a61=(a39*a06);
  a60=(a60+a61);
  a61=(a40*a56);
  a60=(a60+a61);
  a61=(a60*a08);
  a15=(a15+a61);
  a15=(a15*a41);
  a57=(a57+a15);
  a15=(a52*a36);
  a57=(a57+a15);
  a57=(a57*a42);
  a15=(a56*a25);
  a60=(a60*a35);
  a59=(a59*a08);
  a60=(a60-a59);
  a60=(a60*a41);
  a15=(a15+a60);
  a60=(a07*a36);
  a15=(a15+a60);
  a15=(a15*a38);
  a57=(a57+a15);
  a15=(a58*a25);
  a60=(a58*a32);
  a59=(a48*a06);
  a60=(a60+a59);
  a59=(a49*a56);
  a60=(a60+a59);
  a59=(a60*a41);
  a15=(a15+a59);
  a59=(a02*a36);
  a15=(a15+a59);
  a15=(a15*a50);
  a57=(a57+a15);
  a15=(a52*a44);
  a59=(a07*a46);
  a15=(a15+a59);
  a59=(a02*a45);
  a15=(a15+a59);
  a59=arg[0]? arg[0][1] : 0;
  a15=(a15+a59);
  a61=(a15*a25);
  a62=(a58*a53);
  a06=(a06*a55);
  a62=(a62+a06);
  a56=(a56*a20);
  a62=(a62+a56);
  a62=(a62+a15);
  a56=(a62*a41);
  a61=(a61+a56);
  a56=(a36*a59);
  a61=(a61+a56);
  a57=(a57+a61);
  if (res[0]!=0) res[0][1]=a57;
  a11=(a11*a03);
  a11=(a11+a14);
  a00=(a00*a11);
  a10=(a10*a13);
  a10=(a10+a22);
  a09=(a09*a10);
  a00=(a00+a09);
  a01=(a01+a04);
  a16=(a16*a01);
  a00=(a00+a16);
  a16=(a00*a19);
  a21=(a21*a11);
  a23=(a23*a10);
  a21=(a21+a23);
  a24=(a24*a01);
  a21=(a21+a24);
  a24=(a21*a18);
  a16=(a16+a24);
  a24=(a16*a25);
  a27=(a27*a11);
  a29=(a29*a10);
  a27=(a27+a29);
  a30=(a30*a01);
  a27=(a27+a30);
  a31=(a27*a31);
  a33=(a33*a16);
  a31=(a31+a33);
  a21=(a21*a19);
  a00=(a00*a18);
  a21=(a21-a00);
  a34=(a34*a21);
  a31=(a31+a34);
  a34=(a31*a35);
  a37=(a27*a37);
  a39=(a39*a16);
  a37=(a37+a39);
  a40=(a40*a21);
  a37=(a37+a40);
  a40=(a37*a08);
  a34=(a34+a40);
  a34=(a34*a41);
  a24=(a24+a34);
  a34=(a11*a36);
  a24=(a24+a34);
  a24=(a24*a42);
  a42=(a21*a25);
  a37=(a37*a35);
  a31=(a31*a08);
  a37=(a37-a31);
  a37=(a37*a41);
  a42=(a42+a37);
  a37=(a10*a36);
  a42=(a42+a37);
  a42=(a42*a38);
  a24=(a24+a42);
  a42=(a27*a25);
  a32=(a27*a32);
  a48=(a48*a16);
  a32=(a32+a48);
  a49=(a49*a21);
  a32=(a32+a49);
  a49=(a32*a41);
  a42=(a42+a49);
  a49=(a01*a36);
  a42=(a42+a49);
  a42=(a42*a50);
  a24=(a24+a42);
  a44=(a11*a44);
  a46=(a10*a46);
  a44=(a44+a46);
  a45=(a01*a45);
  a44=(a44+a45);
  a45=arg[0]? arg[0][2] : 0;
  a44=(a44+a45);
  a46=(a44*a25);
  a53=(a27*a53);
  a16=(a16*a55);
  a53=(a53+a16);
  a21=(a21*a20);
  a53=(a53+a21);
  a53=(a53+a44);
  a21=(a53*a41);
  a46=(a46+a21);
  a36=(a36*a45);
  a46=(a46+a36);
  a24=(a24+a46);
  if (res[0]!=0) res[0][2]=a24;
  if (res[1]!=0) res[1][0]=a05;
  if (res[1]!=0) res[1][1]=a52;
  if (res[1]!=0) res[1][2]=a11;
  if (res[1]!=0) res[1][3]=a12;
  if (res[1]!=0) res[1][4]=a07;
  if (res[1]!=0) res[1][5]=a10;
  if (res[1]!=0) res[1][6]=a17;
  if (res[1]!=0) res[1][7]=a02;
  if (res[1]!=0) res[1][8]=a01;
  a45=(a24-a45);
  a46=(a52*a45);
  a59=(a57-a59);
  a36=(a11*a59);
  a46=(a46-a36);
  if (res[1]!=0) res[1][9]=a46;
  a51=(a26-a51);
  a11=(a11*a51);
  a46=(a05*a45);
  a11=(a11-a46);
  if (res[1]!=0) res[1][10]=a11;
  a05=(a05*a59);
  a52=(a52*a51);
  a05=(a05-a52);
  if (res[1]!=0) res[1][11]=a05;
  a05=(a07*a45);
  a52=(a10*a59);
  a05=(a05-a52);
  if (res[1]!=0) res[1][12]=a05;
  a10=(a10*a51);
  a05=(a12*a45);
  a10=(a10-a05);
  if (res[1]!=0) res[1][13]=a10;
  a12=(a12*a59);
  a07=(a07*a51);
  a12=(a12-a07);
  if (res[1]!=0) res[1][14]=a12;
  a12=(a02*a45);
  a07=(a01*a59);
  a12=(a12-a07);
  if (res[1]!=0) res[1][15]=a12;
  a01=(a01*a51);
  a45=(a17*a45);
  a01=(a01-a45);
  if (res[1]!=0) res[1][16]=a01;
  a17=(a17*a59);
  a02=(a02*a51);
  a17=(a17-a02);
  if (res[1]!=0) res[1][17]=a17;
  a25=(a25+a41);
  a44=(a24-a44);
  a17=(a58*a44);
  a15=(a57-a15);
  a02=(a27*a15);
  a17=(a17-a02);
  a17=(a25*a17);
  if (res[1]!=0) res[1][18]=a17;
  a43=(a26-a43);
  a27=(a27*a43);
  a44=(a28*a44);
  a27=(a27-a44);
  a27=(a25*a27);
  if (res[1]!=0) res[1][19]=a27;
  a28=(a28*a15);
  a58=(a58*a43);
  a28=(a28-a58);
  a25=(a25*a28);
  if (res[1]!=0) res[1][20]=a25;
  a24=(a24-a53);
  a53=(a60*a24);
  a57=(a57-a62);
  a62=(a32*a57);
  a53=(a53-a62);
  a53=(a41*a53);
  if (res[1]!=0) res[1][21]=a53;
  a26=(a26-a54);
  a32=(a32*a26);
  a24=(a47*a24);
  a32=(a32-a24);
  a32=(a41*a32);
  if (res[1]!=0) res[1][22]=a32;
  a47=(a47*a57);
  a60=(a60*a26);
  a47=(a47-a60);
  a41=(a41*a47);
  if (res[1]!=0) res[1][23]=a41;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_jacobian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_jacobian_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_point_jacobian_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_point_jacobian_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_point_jacobian_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_point_jacobian_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_point_jacobian_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_point_jacobian_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_point_jacobian_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    case 2: return "link";
    case 3: return "point";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_point_jacobian_name_out(casadi_int i) {
  switch (i) {
    case 0: return "position";
    case 1: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_point_jacobian_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_point_jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_jacobian_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_point_jacobian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 2*sizeof(casadi_real*);
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

/* snakecg_sp2_point_jacobian_sincos: 464 CasADi instructions, printed one per line */
static void snakecg_sp2_point_jacobian_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    casadi_real* restrict res0,
    casadi_real* restrict res1) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58, w59;
  casadi_real w60, w61, w62;
  w0 = arg1[69];
  w1 = 1.0;
  w2 = (-2.0);
  w3 = arg0[4];
  w4 = w3 * w3;
  w4 = w2 * w4;
  w5 = w1 + w4;
  w6 = arg0[5];
  w7 = w6 * w6;
  w7 = w2 * w7;
  w5 = w5 + w7;
  w8 = w0 * w5;
  w9 = arg1[70];
  w10 = arg0[6];
  w11 = w2 * w10;
  w12 = w11 * w6;
  w13 = arg0[3];
  w14 = w13 + w13;
  w15 = w14 * w3;
  w12 = w12 + w15;
  w16 = w9 * w12;
  w8 = w8 + w16;
  w16 = arg1[71];
  w10 = w10 + w10;
  w17 = w10 * w3;
  w14 = w14 * w6;
  w17 = w17 + w14;
  w18 = w16 * w17;
  w8 = w8 + w18;
  w18 = arg4[0];
  w19 = w8 * w18;
  w20 = arg1[72];
  w21 = w20 * w5;
  w22 = arg1[73];
  w23 = w22 * w12;
  w21 = w21 + w23;
  w23 = arg1[74];
  w24 = w23 * w17;
  w21 = w21 + w24;
  w24 = arg5[0];
  w25 = w21 * w24;
  w19 = w19 + w25;
  w25 = arg2[1];
  w26 = w19 * w25;
  w27 = arg1[75];
  w28 = w27 * w5;
  w29 = arg1[76];
  w30 = w29 * w12;
  w28 = w28 + w30;
  w30 = arg1[77];
  w31 = w30 * w17;
  w28 = w28 + w31;
  w31 = arg1[80];
  w32 = w28 * w31;
  w33 = arg1[78];
  w34 = w33 * w19;
  w32 = w32 + w34;
  w34 = arg1[79];
  w21 = w21 * w18;
  w8 = w8 * w24;
  w21 = w21 - w8;
  w8 = w34 * w21;
  w32 = w32 + w8;
  w8 = arg4[1];
  w35 = w32 * w8;
  w36 = arg1[83];
  w37 = w28 * w36;
  w38 = arg1[81];
  w39 = w38 * w19;
  w37 = w37 + w39;
  w39 = arg1[82];
  w40 = w39 * w21;
  w37 = w37 + w40;
  w40 = arg5[1];
  w41 = w37 * w40;
  w35 = w35 + w41;
  w41 = arg2[2];
  w35 = w35 * w41;
  w26 = w26 + w35;
  w35 = arg2[0];
  w42 = w5 * w35;
  w26 = w26 + w42;
  w42 = arg1[51];
  w42 = w42 * w25;
  w42 = w35 + w42;
  w43 = arg1[60];
  w43 = w43 * w41;
  w42 = w42 + w43;
  w43 = arg3[0];
  w42 = w42 * w43;
  w44 = arg1[52];
  w44 = w44 * w25;
  w45 = arg1[61];
  w45 = w45 * w41;
  w44 = w44 + w45;
  w45 = arg3[1];
  w44 = w44 * w45;
  w42 = w42 + w44;
  w44 = arg1[53];
  w44 = w44 * w25;
  w46 = arg1[62];
  w46 = w46 * w41;
  w44 = w44 + w46;
  w46 = arg3[2];
  w44 = w44 * w46;
  w42 = w42 + w44;
  w26 = w26 * w42;
  w44 = w21 * w25;
  w37 = w37 * w8;
  w32 = w32 * w40;
  w37 = w37 - w32;
  w37 = w37 * w41;
  w44 = w44 + w37;
  w37 = w12 * w35;
  w44 = w44 + w37;
  w37 = arg1[54];
  w37 = w37 * w25;
  w32 = arg1[63];
  w32 = w32 * w41;
  w37 = w37 + w32;
  w37 = w37 * w43;
  w32 = arg1[55];
  w32 = w32 * w25;
  w32 = w35 + w32;
  w47 = arg1[64];
  w47 = w47 * w41;
  w32 = w32 + w47;
  w32 = w32 * w45;
  w37 = w37 + w32;
  w32 = arg1[56];
  w32 = w32 * w25;
  w47 = arg1[65];
  w47 = w47 * w41;
  w32 = w32 + w47;
  w32 = w32 * w46;
  w37 = w37 + w32;
  w44 = w44 * w37;
  w26 = w26 + w44;
  w44 = w28 * w25;
  w32 = arg1[86];
  w47 = w28 * w32;
  w48 = arg1[84];
  w49 = w48 * w19;
  w47 = w47 + w49;
  w49 = arg1[85];
  w50 = w49 * w21;
  w47 = w47 + w50;
  w50 = w47 * w41;
  w44 = w44 + w50;
  w50 = w17 * w35;
  w44 = w44 + w50;
  w50 = arg1[57];
  w50 = w50 * w25;
  w51 = arg1[66];
  w51 = w51 * w41;
  w50 = w50 + w51;
  w50 = w50 * w43;
  w43 = arg1[58];
  w43 = w43 * w25;
  w51 = arg1[67];
  w51 = w51 * w41;
  w43 = w43 + w51;
  w43 = w43 * w45;
  w50 = w50 + w43;
  w43 = arg1[59];
  w43 = w43 * w25;
  w43 = w35 + w43;
  w45 = arg1[68];
  w45 = w45 * w41;
  w43 = w43 + w45;
  w43 = w43 * w46;
  w50 = w50 + w43;
  w44 = w44 * w50;
  w26 = w26 + w44;
  w44 = arg1[87];
  w43 = w5 * w44;
  w46 = arg1[88];
  w45 = w12 * w46;
  w43 = w43 + w45;
  w45 = arg1[89];
  w51 = w17 * w45;
  w43 = w43 + w51;
  w51 = arg0[0];
  w43 = w43 + w51;
  w52 = w43 * w25;
  w53 = arg1[92];
  w54 = w28 * w53;
  w55 = arg1[90];
  w19 = w19 * w55;
  w54 = w54 + w19;
  w19 = arg1[91];
  w21 = w21 * w19;
  w54 = w54 + w21;
  w54 = w54 + w43;
  w21 = w54 * w41;
  w52 = w52 + w21;
  w21 = w35 * w51;
  w52 = w52 + w21;
  w26 = w26 + w52;
  res0[0] = w26;
  w52 = w10 * w6;
  w52 = w52 + w15;
  w15 = w0 * w52;
  w21 = w13 * w13;
  w2 = w2 * w21;
  w1 = w1 + w2;
  w7 = w1 + w7;
  w2 = w9 * w7;
  w15 = w15 + w2;
  w2 = w11 * w13;
  w21 = w3 + w3;
  w21 = w21 * w6;
  w2 = w2 + w21;
  w6 = w16 * w2;
  w15 = w15 + w6;
  w6 = w15 * w18;
  w56 = w20 * w52;
  w57 = w22 * w7;
  w56 = w56 + w57;
  w57 = w23 * w2;
  w56 = w56 + w57;
  w57 = w56 * w24;
  w6 = w6 + w57;
  w57 = w6 * w25;
  w58 = w27 * w52;
  w59 = w29 * w7;
  w58 = w58 + w59;
  w59 = w30 * w2;
  w58 = w58 + w59;
  w59 = w58 * w31;
  w60 = w33 * w6;
  w59 = w59 + w60;
  w56 = w56 * w18;
  w15 = w15 * w24;
  w56 = w56 - w15;
  w15 = w34 * w56;
  w59 = w59 + w15;
  w15 = w59 * w8;
  w60 = w58 * w36;
  w61 = w38 * w6;
  w60 = w60 + w61;
  w61 = w39 * w56;
  w60 = w60 + w61;
  w61 = w60 * w40;
  w15 = w15 + w61;
  w15 = w15 * w41;
  w57 = w57 + w15;
  w15 = w52 * w35;
  w57 = w57 + w15;
  w57 = w57 * w42;
  w15 = w56 * w25;
  w60 = w60 * w8;
  w59 = w59 * w40;
  w60 = w60 - w59;
  w60 = w60 * w41;
  w15 = w15 + w60;
  w60 = w7 * w35;
  w15 = w15 + w60;
  w15 = w15 * w37;
  w57 = w57 + w15;
  w15 = w58 * w25;
  w60 = w58 * w32;
  w59 = w48 * w6;
  w60 = w60 + w59;
  w59 = w49 * w56;
  w60 = w60 + w59;
  w59 = w60 * w41;
  w15 = w15 + w59;
  w59 = w2 * w35;
  w15 = w15 + w59;
  w15 = w15 * w50;
  w57 = w57 + w15;
  w15 = w52 * w44;
  w59 = w7 * w46;
  w15 = w15 + w59;
  w59 = w2 * w45;
  w15 = w15 + w59;
  w59 = arg0[1];
  w15 = w15 + w59;
  w61 = w15 * w25;
  w62 = w58 * w53;
  w6 = w6 * w55;
  w62 = w62 + w6;
  w56 = w56 * w19;
  w62 = w62 + w56;
  w62 = w62 + w15;
  w56 = w62 * w41;
  w61 = w61 + w56;
  w56 = w35 * w59;
  w61 = w61 + w56;
  w57 = w57 + w61;
  res0[1] = w57;
  w11 = w11 * w3;
  w11 = w11 + w14;
  w0 = w0 * w11;
  w10 = w10 * w13;
  w10 = w10 + w21;
  w9 = w9 * w10;
  w0 = w0 + w9;
  w1 = w1 + w4;
  w16 = w16 * w1;
  w0 = w0 + w16;
  w16 = w0 * w18;
  w20 = w20 * w11;
  w22 = w22 * w10;
  w20 = w20 + w22;
  w23 = w23 * w1;
  w20 = w20 + w23;
  w23 = w20 * w24;
  w16 = w16 + w23;
  w23 = w16 * w25;
  w27 = w27 * w11;
  w29 = w29 * w10;
  w27 = w27 + w29;
  w30 = w30 * w1;
  w27 = w27 + w30;
  w31 = w27 * w31;
  w33 = w33 * w16;
  w31 = w31 + w33;
  w20 = w20 * w18;
  w0 = w0 * w24;
  w20 = w20 - w0;
  w34 = w34 * w20;
  w31 = w31 + w34;
  w34 = w31 * w8;
  w36 = w27 * w36;
  w38 = w38 * w16;
  w36 = w36 + w38;
  w39 = w39 * w20;
  w36 = w36 + w39;
  w39 = w36 * w40;
  w34 = w34 + w39;
  w34 = w34 * w41;
  w23 = w23 + w34;
  w34 = w11 * w35;
  w23 = w23 + w34;
  w23 = w23 * w42;
  w42 = w20 * w25;
  w36 = w36 * w8;
  w31 = w31 * w40;
  w36 = w36 - w31;
  w36 = w36 * w41;
  w42 = w42 + w36;
  w36 = w10 * w35;
  w42 = w42 + w36;
  w42 = w42 * w37;
  w23 = w23 + w42;
  w42 = w27 * w25;
  w32 = w27 * w32;
  w48 = w48 * w16;
  w32 = w32 + w48;
  w49 = w49 * w20;
  w32 = w32 + w49;
  w49 = w32 * w41;
  w42 = w42 + w49;
  w49 = w1 * w35;
  w42 = w42 + w49;
  w42 = w42 * w50;
  w23 = w23 + w42;
  w44 = w11 * w44;
  w46 = w10 * w46;
  w44 = w44 + w46;
  w45 = w1 * w45;
  w44 = w44 + w45;
  w45 = arg0[2];
  w44 = w44 + w45;
  w46 = w44 * w25;
  w53 = w27 * w53;
  w16 = w16 * w55;
  w53 = w53 + w16;
  w20 = w20 * w19;
  w53 = w53 + w20;
  w53 = w53 + w44;
  w20 = w53 * w41;
  w46 = w46 + w20;
  w35 = w35 * w45;
  w46 = w46 + w35;
  w23 = w23 + w46;
  res0[2] = w23;
  res1[0] = w5;
  res1[1] = w52;
  res1[2] = w11;
  res1[3] = w12;
  res1[4] = w7;
  res1[5] = w10;
  res1[6] = w17;
  res1[7] = w2;
  res1[8] = w1;
  w45 = w23 - w45;
  w46 = w52 * w45;
  w59 = w57 - w59;
  w35 = w11 * w59;
  w46 = w46 - w35;
  res1[9] = w46;
  w51 = w26 - w51;
  w11 = w11 * w51;
  w46 = w5 * w45;
  w11 = w11 - w46;
  res1[10] = w11;
  w5 = w5 * w59;
  w52 = w52 * w51;
  w5 = w5 - w52;
  res1[11] = w5;
  w5 = w7 * w45;
  w52 = w10 * w59;
  w5 = w5 - w52;
  res1[12] = w5;
  w10 = w10 * w51;
  w5 = w12 * w45;
  w10 = w10 - w5;
  res1[13] = w10;
  w12 = w12 * w59;
  w7 = w7 * w51;
  w12 = w12 - w7;
  res1[14] = w12;
  w12 = w2 * w45;
  w7 = w1 * w59;
  w12 = w12 - w7;
  res1[15] = w12;
  w1 = w1 * w51;
  w45 = w17 * w45;
  w1 = w1 - w45;
  res1[16] = w1;
  w17 = w17 * w59;
  w2 = w2 * w51;
  w17 = w17 - w2;
  res1[17] = w17;
  w25 = w25 + w41;
  w44 = w23 - w44;
  w17 = w58 * w44;
  w15 = w57 - w15;
  w2 = w27 * w15;
  w17 = w17 - w2;
  w17 = w25 * w17;
  res1[18] = w17;
  w43 = w26 - w43;
  w27 = w27 * w43;
  w44 = w28 * w44;
  w27 = w27 - w44;
  w27 = w25 * w27;
  res1[19] = w27;
  w28 = w28 * w15;
  w58 = w58 * w43;
  w28 = w28 - w58;
  w25 = w25 * w28;
  res1[20] = w25;
  w23 = w23 - w53;
  w53 = w60 * w23;
  w57 = w57 - w62;
  w62 = w32 * w57;
  w53 = w53 - w62;
  w53 = w41 * w53;
  res1[21] = w53;
  w26 = w26 - w54;
  w32 = w32 * w26;
  w23 = w47 * w23;
  w32 = w32 - w23;
  w32 = w41 * w32;
  res1[22] = w32;
  w47 = w47 * w57;
  w60 = w60 * w26;
  w47 = w47 - w60;
  w41 = w41 * w47;
  res1[23] = w41;
}


CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_point_jacobian(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[2];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 64);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 2; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && res[0] && res[1]) {
    /* cos and sin of q[7..8] of 16 samples at a time, then snakecg_sp2_point_jacobian_sincos
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
        snakecg_sp2_point_jacobian_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], ca + i * na, sa + i * na, res[0] + (i0 + i) * 3, res[1] + (i0 + i) * 24);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      r[0] = res[0] + i * 3;
      r[1] = res[1] + i * 24;
      if (snakecg_sp2_point_jacobian(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
