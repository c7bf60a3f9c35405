/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for ground_rows() of
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
  #define CASADI_PREFIX(ID) snakecg_sp2_ground_rows_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp2_ground_rows_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_ground_rows_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_ground_rows_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {8, 1, 1};
static const casadi_int casadi_s2[3] = {120, 1, 1};
static const casadi_int casadi_s3[3] = {3, 8, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};

/* snakecg_sp2_ground_rows:(q[9],v[8],K[120],support_points[9])->(A[3x8],adot_v[3],height[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72;
  a00=-2.;
  a01=arg[0]? arg[0][6] : 0;
  a02=(a00*a01);
  a03=arg[0]? arg[0][4] : 0;
  a04=(a02*a03);
  a05=arg[0]? arg[0][3] : 0;
  a06=(2.*a05);
  a07=arg[0]? arg[0][5] : 0;
  a08=(a06*a07);
  a04=(a04+a08);
  if (res[0]!=0) res[0][0]=a04;
  if (res[0]!=0) res[0][1]=a04;
  if (res[0]!=0) res[0][2]=a04;
  a01=(2.*a01);
  a09=(a01*a05);
  a10=(2.*a03);
  a10=(a10*a07);
  a09=(a09+a10);
  if (res[0]!=0) res[0][3]=a09;
  if (res[0]!=0) res[0][4]=a09;
  if (res[0]!=0) res[0][5]=a09;
  a11=1.;
  a12=casadi_sq(a05);
  a12=(a00*a12);
  a12=(a11+a12);
  a13=casadi_sq(a03);
  a13=(a00*a13);
  a14=(a12+a13);
  if (res[0]!=0) res[0][6]=a14;
  if (res[0]!=0) res[0][7]=a14;
  if (res[0]!=0) res[0][8]=a14;
  a11=(a11+a13);
  a13=casadi_sq(a07);
  a00=(a00*a13);
  a11=(a11+a00);
  a13=(a01*a07);
  a06=(a06*a03);
  a13=(a13+a06);
  a15=arg[3]? arg[3][0] : 0;
  a16=(a13*a15);
  a12=(a12+a00);
  a00=arg[3]? arg[3][1] : 0;
  a17=(a12*a00);
  a16=(a16+a17);
  a05=(a02*a05);
  a05=(a05+a10);
  a10=arg[3]? arg[3][2] : 0;
  a17=(a05*a10);
  a16=(a16+a17);
  a17=(a11*a16);
  a18=(a11*a15);
  a02=(a02*a07);
  a02=(a02+a06);
  a06=(a02*a00);
  a18=(a18+a06);
  a01=(a01*a03);
  a01=(a01+a08);
  a08=(a01*a10);
  a18=(a18+a08);
  a08=(a13*a18);
  a17=(a17-a08);
  if (res[0]!=0) res[0][9]=a17;
  a17=arg[2]? arg[2][75] : 0;
  a08=(a17*a13);
  a03=arg[2]? arg[2][76] : 0;
  a06=(a03*a12);
  a08=(a08+a06);
  a06=arg[2]? arg[2][77] : 0;
  a07=(a06*a05);
  a08=(a08+a07);
  a07=arg[2]? arg[2][57] : 0;
  a19=arg[3]? arg[3][3] : 0;
  a07=(a07*a19);
  a20=arg[2]? arg[2][58] : 0;
  a21=arg[3]? arg[3][4] : 0;
  a20=(a20*a21);
  a07=(a07+a20);
  a20=arg[2]? arg[2][59] : 0;
  a22=arg[3]? arg[3][5] : 0;
  a20=(a20*a22);
  a07=(a07+a20);
  a20=(a08*a07);
  a23=arg[2]? arg[2][69] : 0;
  a24=(a23*a13);
  a25=arg[2]? arg[2][70] : 0;
  a26=(a25*a12);
  a24=(a24+a26);
  a26=arg[2]? arg[2][71] : 0;
  a27=(a26*a05);
  a24=(a24+a27);
  a27=arg[0]? arg[0][7] : 0;
  a28=cos(a27);
  a29=(a24*a28);
  a30=arg[2]? arg[2][72] : 0;
  a31=(a30*a13);
  a32=arg[2]? arg[2][73] : 0;
  a33=(a32*a12);
  a31=(a31+a33);
  a33=arg[2]? arg[2][74] : 0;
  a34=(a33*a05);
  a31=(a31+a34);
  a27=sin(a27);
  a34=(a31*a27);
  a29=(a29+a34);
  a34=arg[2]? arg[2][51] : 0;
  a34=(a34*a19);
  a35=arg[2]? arg[2][52] : 0;
  a35=(a35*a21);
  a34=(a34+a35);
  a35=arg[2]? arg[2][53] : 0;
  a35=(a35*a22);
  a34=(a34+a35);
  a35=(a29*a34);
  a20=(a20+a35);
  a31=(a31*a28);
  a24=(a24*a27);
  a31=(a31-a24);
  a24=arg[2]? arg[2][54] : 0;
  a24=(a24*a19);
  a19=arg[2]? arg[2][55] : 0;
  a19=(a19*a21);
  a24=(a24+a19);
  a19=arg[2]? arg[2][56] : 0;
  a19=(a19*a22);
  a24=(a24+a19);
  a19=(a31*a24);
  a20=(a20+a19);
  a19=arg[2]? arg[2][87] : 0;
  a22=(a13*a19);
  a21=arg[2]? arg[2][88] : 0;
  a35=(a12*a21);
  a22=(a22+a35);
  a35=arg[2]? arg[2][89] : 0;
  a36=(a05*a35);
  a22=(a22+a36);
  a36=arg[0]? arg[0][1] : 0;
  a37=(a22+a36);
  a38=(a20+a37);
  a38=(a38-a36);
  a39=(a11*a38);
  a40=(a17*a11);
  a41=(a03*a02);
  a40=(a40+a41);
  a41=(a06*a01);
  a40=(a40+a41);
  a41=(a40*a07);
  a42=(a23*a11);
  a43=(a25*a02);
  a42=(a42+a43);
  a43=(a26*a01);
  a42=(a42+a43);
  a43=(a42*a28);
  a44=(a30*a11);
  a45=(a32*a02);
  a44=(a44+a45);
  a45=(a33*a01);
  a44=(a44+a45);
  a45=(a44*a27);
  a43=(a43+a45);
  a45=(a43*a34);
  a41=(a41+a45);
  a44=(a44*a28);
  a42=(a42*a27);
  a44=(a44-a42);
  a42=(a44*a24);
  a41=(a41+a42);
  a42=(a11*a19);
  a45=(a02*a21);
  a42=(a42+a45);
  a45=(a01*a35);
  a42=(a42+a45);
  a45=arg[0]? arg[0][0] : 0;
  a46=(a42+a45);
  a47=(a41+a46);
  a47=(a47-a45);
  a48=(a13*a47);
  a39=(a39-a48);
  if (res[0]!=0) res[0][10]=a39;
  a39=arg[2]? arg[2][86] : 0;
  a48=(a08*a39);
  a49=arg[2]? arg[2][84] : 0;
  a50=(a49*a29);
  a48=(a48+a50);
  a50=arg[2]? arg[2][85] : 0;
  a51=(a50*a31);
  a48=(a48+a51);
  a51=arg[2]? arg[2][66] : 0;
  a52=arg[3]? arg[3][6] : 0;
  a51=(a51*a52);
  a53=arg[2]? arg[2][67] : 0;
  a54=arg[3]? arg[3][7] : 0;
  a53=(a53*a54);
  a51=(a51+a53);
  a53=arg[2]? arg[2][68] : 0;
  a55=arg[3]? arg[3][8] : 0;
  a53=(a53*a55);
  a51=(a51+a53);
  a53=(a48*a51);
  a56=arg[2]? arg[2][80] : 0;
  a57=(a08*a56);
  a58=arg[2]? arg[2][78] : 0;
  a59=(a58*a29);
  a57=(a57+a59);
  a59=arg[2]? arg[2][79] : 0;
  a60=(a59*a31);
  a57=(a57+a60);
  a60=arg[0]? arg[0][8] : 0;
  a61=cos(a60);
  a62=(a57*a61);
  a63=arg[2]? arg[2][83] : 0;
  a64=(a08*a63);
  a65=arg[2]? arg[2][81] : 0;
  a66=(a65*a29);
  a64=(a64+a66);
  a66=arg[2]? arg[2][82] : 0;
  a67=(a66*a31);
  a64=(a64+a67);
  a60=sin(a60);
  a67=(a64*a60);
  a62=(a62+a67);
  a67=arg[2]? arg[2][60] : 0;
  a67=(a67*a52);
  a68=arg[2]? arg[2][61] : 0;
  a68=(a68*a54);
  a67=(a67+a68);
  a68=arg[2]? arg[2][62] : 0;
  a68=(a68*a55);
  a67=(a67+a68);
  a62=(a62*a67);
  a53=(a53+a62);
  a64=(a64*a61);
  a57=(a57*a60);
  a64=(a64-a57);
  a57=arg[2]? arg[2][63] : 0;
  a57=(a57*a52);
  a52=arg[2]? arg[2][64] : 0;
  a52=(a52*a54);
  a57=(a57+a52);
  a52=arg[2]? arg[2][65] : 0;
  a52=(a52*a55);
  a57=(a57+a52);
  a64=(a64*a57);
  a53=(a53+a64);
  a64=arg[2]? arg[2][92] : 0;
  a52=(a08*a64);
  a55=arg[2]? arg[2][90] : 0;
  a29=(a29*a55);
  a52=(a52+a29);
  a29=arg[2]? arg[2][91] : 0;
  a31=(a31*a29);
  a52=(a52+a31);
  a31=(a52+a37);
  a31=(a53+a31);
  a36=(a31-a36);
  a54=(a11*a36);
  a62=(a40*a39);
  a68=(a49*a43);
  a62=(a62+a68);
  a68=(a50*a44);
  a62=(a62+a68);
  a68=(a62*a51);
  a69=(a40*a56);
  a70=(a58*a43);
  a69=(a69+a70);
  a70=(a59*a44);
  a69=(a69+a70);
  a70=(a69*a61);
  a71=(a40*a63);
  a72=(a65*a43);
  a71=(a71+a72);
  a72=(a66*a44);
  a71=(a71+a72);
  a72=(a71*a60);
  a70=(a70+a72);
  a70=(a70*a67);
  a68=(a68+a70);
  a71=(a71*a61);
  a69=(a69*a60);
  a71=(a71-a69);
  a71=(a71*a57);
  a68=(a68+a71);
  a71=(a40*a64);
  a43=(a43*a55);
  a71=(a71+a43);
  a44=(a44*a29);
  a71=(a71+a44);
  a44=(a71+a46);
  a44=(a68+a44);
  a45=(a44-a45);
  a43=(a13*a45);
  a54=(a54-a43);
  if (res[0]!=0) res[0][11]=a54;
  a54=(a02*a16);
  a43=(a12*a18);
  a54=(a54-a43);
  if (res[0]!=0) res[0][12]=a54;
  a54=(a02*a38);
  a43=(a12*a47);
  a54=(a54-a43);
  if (res[0]!=0) res[0][13]=a54;
  a54=(a02*a36);
  a43=(a12*a45);
  a54=(a54-a43);
  if (res[0]!=0) res[0][14]=a54;
  a54=(a01*a16);
  a43=(a05*a18);
  a54=(a54-a43);
  if (res[0]!=0) res[0][15]=a54;
  a38=(a01*a38);
  a47=(a05*a47);
  a38=(a38-a47);
  if (res[0]!=0) res[0][16]=a38;
  a36=(a01*a36);
  a45=(a05*a45);
  a36=(a36-a45);
  if (res[0]!=0) res[0][17]=a36;
  a36=0.;
  if (res[0]!=0) res[0][18]=a36;
  a45=(a40*a20);
  a38=(a08*a41);
  a45=(a45-a38);
  if (res[0]!=0) res[0][19]=a45;
  a31=(a31-a37);
  a31=(a40*a31);
  a44=(a44-a46);
  a44=(a08*a44);
  a31=(a31-a44);
  if (res[0]!=0) res[0][20]=a31;
  if (res[0]!=0) res[0][21]=a36;
  if (res[0]!=0) res[0][22]=a36;
  a36=(a62*a53);
  a31=(a48*a68);
  a36=(a36-a31);
  if (res[0]!=0) res[0][23]=a36;
  a36=arg[1]? arg[1][3] : 0;
  a31=(a11*a36);
  a44=arg[1]? arg[1][4] : 0;
  a46=(a02*a44);
  a31=(a31+a46);
  a46=arg[1]? arg[1][5] : 0;
  a37=(a01*a46);
  a31=(a31+a37);
  a37=arg[1]? arg[1][0] : 0;
  a45=(a13*a37);
  a38=arg[1]? arg[1][1] : 0;
  a47=(a12*a38);
  a45=(a45+a47);
  a47=arg[1]? arg[1][2] : 0;
  a54=(a05*a47);
  a45=(a45+a54);
  a45=(a31*a45);
  a13=(a13*a36);
  a12=(a12*a44);
  a13=(a13+a12);
  a05=(a05*a46);
  a13=(a13+a05);
  a11=(a11*a37);
  a02=(a02*a38);
  a11=(a11+a02);
  a01=(a01*a47);
  a11=(a11+a01);
  a11=(a13*a11);
  a45=(a45-a11);
  a36=(a04*a36);
  a44=(a09*a44);
  a36=(a36+a44);
  a46=(a14*a46);
  a36=(a36+a46);
  a18=(a18*a36);
  a15=(a04*a15);
  a00=(a09*a00);
  a15=(a15+a00);
  a10=(a14*a10);
  a15=(a15+a10);
  a10=(a15*a31);
  a18=(a18-a10);
  a18=(a18*a31);
  a18=(a45+a18);
  a10=(a15*a13);
  a16=(a16*a36);
  a10=(a10-a16);
  a10=(a10*a13);
  a18=(a18-a10);
  if (res[1]!=0) res[1][0]=a18;
  a42=(a42*a36);
  a19=(a04*a19);
  a21=(a09*a21);
  a19=(a19+a21);
  a35=(a14*a35);
  a19=(a19+a35);
  a35=(a19*a31);
  a42=(a42-a35);
  a42=(a31*a42);
  a45=(a45+a42);
  a42=(a19*a13);
  a22=(a22*a36);
  a42=(a42-a22);
  a42=(a13*a42);
  a45=(a45-a42);
  a42=arg[1]? arg[1][6] : 0;
  a17=(a17*a04);
  a03=(a03*a09);
  a17=(a17+a03);
  a06=(a06*a14);
  a17=(a17+a06);
  a06=(a17*a13);
  a03=(a08*a36);
  a06=(a06-a03);
  a06=(a42*a06);
  a03=(a06*a20);
  a03=(a45+a03);
  a22=(a17*a42);
  a22=(a36+a22);
  a35=(a41*a22);
  a07=(a17*a07);
  a23=(a23*a04);
  a25=(a25*a09);
  a23=(a23+a25);
  a26=(a26*a14);
  a23=(a23+a26);
  a26=(a23*a28);
  a30=(a30*a04);
  a32=(a32*a09);
  a30=(a30+a32);
  a33=(a33*a14);
  a30=(a30+a33);
  a33=(a30*a27);
  a26=(a26+a33);
  a34=(a26*a34);
  a07=(a07+a34);
  a30=(a30*a28);
  a23=(a23*a27);
  a30=(a30-a23);
  a24=(a30*a24);
  a07=(a07+a24);
  a24=(a40*a42);
  a24=(a31+a24);
  a23=(a07*a24);
  a35=(a35-a23);
  a35=(a35*a24);
  a03=(a03+a35);
  a40=(a40*a36);
  a31=(a17*a31);
  a40=(a40-a31);
  a40=(a42*a40);
  a41=(a40*a41);
  a03=(a03-a41);
  a08=(a08*a42);
  a13=(a13+a08);
  a08=(a07*a13);
  a20=(a20*a22);
  a08=(a08-a20);
  a08=(a08*a13);
  a03=(a03-a08);
  if (res[1]!=0) res[1][1]=a03;
  a03=(a06*a52);
  a45=(a45+a03);
  a03=(a71*a22);
  a64=(a17*a64);
  a55=(a26*a55);
  a64=(a64+a55);
  a29=(a30*a29);
  a64=(a64+a29);
  a29=(a64*a24);
  a03=(a03-a29);
  a03=(a24*a03);
  a45=(a45+a03);
  a71=(a40*a71);
  a45=(a45-a71);
  a71=(a64*a13);
  a52=(a52*a22);
  a71=(a71-a52);
  a71=(a13*a71);
  a45=(a45-a71);
  a71=arg[1]? arg[1][7] : 0;
  a39=(a17*a39);
  a49=(a49*a26);
  a39=(a39+a49);
  a50=(a50*a30);
  a39=(a39+a50);
  a50=(a39*a13);
  a49=(a48*a22);
  a50=(a50-a49);
  a50=(a71*a50);
  a06=(a06+a50);
  a06=(a06*a53);
  a45=(a45+a06);
  a06=(a39*a71);
  a06=(a22+a06);
  a50=(a68*a06);
  a51=(a39*a51);
  a56=(a17*a56);
  a58=(a58*a26);
  a56=(a56+a58);
  a59=(a59*a30);
  a56=(a56+a59);
  a59=(a56*a61);
  a17=(a17*a63);
  a65=(a65*a26);
  a17=(a17+a65);
  a66=(a66*a30);
  a17=(a17+a66);
  a66=(a17*a60);
  a59=(a59+a66);
  a59=(a59*a67);
  a51=(a51+a59);
  a17=(a17*a61);
  a56=(a56*a60);
  a17=(a17-a56);
  a17=(a17*a57);
  a51=(a51+a17);
  a17=(a62*a71);
  a17=(a24+a17);
  a57=(a51*a17);
  a50=(a50-a57);
  a50=(a50*a17);
  a45=(a45+a50);
  a62=(a62*a22);
  a39=(a39*a24);
  a62=(a62-a39);
  a62=(a71*a62);
  a40=(a40+a62);
  a40=(a40*a68);
  a45=(a45-a40);
  a48=(a48*a71);
  a13=(a13+a48);
  a48=(a51*a13);
  a53=(a53*a06);
  a48=(a48-a53);
  a48=(a48*a13);
  a45=(a45-a48);
  if (res[1]!=0) res[1][2]=a45;
  a45=arg[0]? arg[0][2] : 0;
  a15=(a15+a45);
  if (res[2]!=0) res[2][0]=a15;
  a19=(a19+a45);
  a07=(a07+a19);
  if (res[2]!=0) res[2][1]=a07;
  a64=(a64+a19);
  a51=(a51+a64);
  if (res[2]!=0) res[2][2]=a51;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_ground_rows(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_ground_rows_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_ground_rows_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_ground_rows_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_ground_rows_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_ground_rows_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_ground_rows_n_out(void) { return 3;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_ground_rows_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_ground_rows_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "support_points";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_ground_rows_name_out(casadi_int i) {
  switch (i) {
    case 0: return "A";
    case 1: return "adot_v";
    case 2: return "height";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_ground_rows_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_ground_rows_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    case 2: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_ground_rows_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 3;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_ground_rows_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 3*sizeof(casadi_real*);
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

/* snakecg_sp2_ground_rows_sincos: 539 CasADi instructions, printed one per line */
static void snakecg_sp2_ground_rows_sincos(
    const casadi_real* restrict arg0,
    const casadi_real* restrict arg1,
    const casadi_real* restrict arg2,
    const casadi_real* restrict arg3,
    const casadi_real* restrict arg4,
    const casadi_real* restrict arg5,
    casadi_real* restrict res0,
    casadi_real* restrict res1,
    casadi_real* restrict res2) {
  casadi_real w0, w1, w2, w3, w4, w5, w6, w7, w8, w9;
  casadi_real w10, w11, w12, w13, w14, w15, w16, w17, w18, w19;
  casadi_real w20, w21, w22, w23, w24, w25, w26, w27, w28, w29;
  casadi_real w30, w31, w32, w33, w34, w35, w36, w37, w38, w39;
  casadi_real w40, w41, w42, w43, w44, w45, w46, w47, w48, w49;
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58, w59;
  casadi_real w60, w61, w62, w63, w64, w65, w66, w67, w68, w69;
  casadi_real w70, w71, w72;
  w0 = (-2.0);
  w1 = arg0[6];
  w2 = w0 * w1;
  w3 = arg0[4];
  w4 = w2 * w3;
  w5 = arg0[3];
  w6 = w5 + w5;
  w7 = arg0[5];
  w8 = w6 * w7;
  w4 = w4 + w8;
  res0[0] = w4;
  res0[1] = w4;
  res0[2] = w4;
  w1 = w1 + w1;
  w9 = w1 * w5;
  w10 = w3 + w3;
  w10 = w10 * w7;
  w9 = w9 + w10;
  res0[3] = w9;
  res0[4] = w9;
  res0[5] = w9;
  w11 = 1.0;
  w12 = w5 * w5;
  w12 = w0 * w12;
  w12 = w11 + w12;
  w13 = w3 * w3;
  w13 = w0 * w13;
  w14 = w12 + w13;
  res0[6] = w14;
  res0[7] = w14;
  res0[8] = w14;
  w11 = w11 + w13;
  w13 = w7 * w7;
  w0 = w0 * w13;
  w11 = w11 + w0;
  w13 = w1 * w7;
  w6 = w6 * w3;
  w13 = w13 + w6;
  w15 = arg3[0];
  w16 = w13 * w15;
  w12 = w12 + w0;
  w0 = arg3[1];
  w17 = w12 * w0;
  w16 = w16 + w17;
  w5 = w2 * w5;
  w5 = w5 + w10;
  w10 = arg3[2];
  w17 = w5 * w10;
  w16 = w16 + w17;
  w17 = w11 * w16;
  w18 = w11 * w15;
  w2 = w2 * w7;
  w2 = w2 + w6;
  w6 = w2 * w0;
  w18 = w18 + w6;
  w1 = w1 * w3;
  w1 = w1 + w8;
  w8 = w1 * w10;
  w18 = w18 + w8;
  w8 = w13 * w18;
  w17 = w17 - w8;
  res0[9] = w17;
  w17 = arg2[75];
  w8 = w17 * w13;
  w3 = arg2[76];
  w6 = w3 * w12;
  w8 = w8 + w6;
  w6 = arg2[77];
  w7 = w6 * w5;
  w8 = w8 + w7;
  w7 = arg2[57];
  w19 = arg3[3];
  w7 = w7 * w19;
  w20 = arg2[58];
  w21 = arg3[4];
  w20 = w20 * w21;
  w7 = w7 + w20;
  w20 = arg2[59];
  w22 = arg3[5];
  w20 = w20 * w22;
  w7 = w7 + w20;
  w20 = w8 * w7;
  w23 = arg2[69];
  w24 = w23 * w13;
  w25 = arg2[70];
  w26 = w25 * w12;
  w24 = w24 + w26;
  w26 = arg2[71];
  w27 = w26 * w5;
  w24 = w24 + w27;
  w27 = arg4[0];
  w28 = w24 * w27;
  w29 = arg2[72];
  w30 = w29 * w13;
  w31 = arg2[73];
  w32 = w31 * w12;
  w30 = w30 + w32;
  w32 = arg2[74];
  w33 = w32 * w5;
  w30 = w30 + w33;
  w33 = arg5[0];
  w34 = w30 * w33;
  w28 = w28 + w34;
  w34 = arg2[51];
  w34 = w34 * w19;
  w35 = arg2[52];
  w35 = w35 * w21;
  w34 = w34 + w35;
  w35 = arg2[53];
  w35 = w35 * w22;
  w34 = w34 + w35;
  w35 = w28 * w34;
  w20 = w20 + w35;
  w30 = w30 * w27;
  w24 = w24 * w33;
  w30 = w30 - w24;
  w24 = arg2[54];
  w24 = w24 * w19;
  w19 = arg2[55];
  w19 = w19 * w21;
  w24 = w24 + w19;
  w19 = arg2[56];
  w19 = w19 * w22;
  w24 = w24 + w19;
  w19 = w30 * w24;
  w20 = w20 + w19;
  w19 = arg2[87];
  w22 = w13 * w19;
  w21 = arg2[88];
  w35 = w12 * w21;
  w22 = w22 + w35;
  w35 = arg2[89];
  w36 = w5 * w35;
  w22 = w22 + w36;
  w36 = arg0[1];
  w37 = w22 + w36;
  w38 = w20 + w37;
  w38 = w38 - w36;
  w39 = w11 * w38;
  w40 = w17 * w11;
  w41 = w3 * w2;
  w40 = w40 + w41;
  w41 = w6 * w1;
  w40 = w40 + w41;
  w41 = w40 * w7;
  w42 = w23 * w11;
  w43 = w25 * w2;
  w42 = w42 + w43;
  w43 = w26 * w1;
  w42 = w42 + w43;
  w43 = w42 * w27;
  w44 = w29 * w11;
  w45 = w31 * w2;
  w44 = w44 + w45;
  w45 = w32 * w1;
  w44 = w44 + w45;
  w45 = w44 * w33;
  w43 = w43 + w45;
  w45 = w43 * w34;
  w41 = w41 + w45;
  w44 = w44 * w27;
  w42 = w42 * w33;
  w44 = w44 - w42;
  w42 = w44 * w24;
  w41 = w41 + w42;
  w42 = w11 * w19;
  w45 = w2 * w21;
  w42 = w42 + w45;
  w45 = w1 * w35;
  w42 = w42 + w45;
  w45 = arg0[0];
  w46 = w42 + w45;
  w47 = w41 + w46;
  w47 = w47 - w45;
  w48 = w13 * w47;
  w39 = w39 - w48;
  res0[10] = w39;
  w39 = arg2[86];
  w48 = w8 * w39;
  w49 = arg2[84];
  w50 = w49 * w28;
  w48 = w48 + w50;
  w50 = arg2[85];
  w51 = w50 * w30;
  w48 = w48 + w51;
  w51 = arg2[66];
  w52 = arg3[6];
  w51 = w51 * w52;
  w53 = arg2[67];
  w54 = arg3[7];
  w53 = w53 * w54;
  w51 = w51 + w53;
  w53 = arg2[68];
  w55 = arg3[8];
  w53 = w53 * w55;
  w51 = w51 + w53;
  w53 = w48 * w51;
  w56 = arg2[80];
  w57 = w8 * w56;
  w58 = arg2[78];
  w59 = w58 * w28;
  w57 = w57 + w59;
  w59 = arg2[79];
  w60 = w59 * w30;
  w57 = w57 + w60;
  w60 = arg4[1];
  w61 = w57 * w60;
  w62 = arg2[83];
  w63 = w8 * w62;
  w64 = arg2[81];
  w65 = w64 * w28;
  w63 = w63 + w65;
  w65 = arg2[82];
  w66 = w65 * w30;
  w63 = w63 + w66;
  w66 = arg5[1];
  w67 = w63 * w66;
  w61 = w61 + w67;
  w67 = arg2[60];
  w67 = w67 * w52;
  w68 = arg2[61];
  w68 = w68 * w54;
  w67 = w67 + w68;
  w68 = arg2[62];
  w68 = w68 * w55;
  w67 = w67 + w68;
  w61 = w61 * w67;
  w53 = w53 + w61;
  w63 = w63 * w60;
  w57 = w57 * w66;
  w63 = w63 - w57;
  w57 = arg2[63];
  w57 = w57 * w52;
  w52 = arg2[64];
  w52 = w52 * w54;
  w57 = w57 + w52;
  w52 = arg2[65];
  w52 = w52 * w55;
  w57 = w57 + w52;
  w63 = w63 * w57;
  w53 = w53 + w63;
  w63 = arg2[92];
  w52 = w8 * w63;
  w55 = arg2[90];
  w28 = w28 * w55;
  w52 = w52 + w28;
  w28 = arg2[91];
  w30 = w30 * w28;
  w52 = w52 + w30;
  w30 = w52 + w37;
  w30 = w53 + w30;
  w36 = w30 - w36;
  w54 = w11 * w36;
  w61 = w40 * w39;
  w68 = w49 * w43;
  w61 = w61 + w68;
  w68 = w50 * w44;
  w61 = w61 + w68;
  w68 = w61 * w51;
  w69 = w40 * w56;
  w70 = w58 * w43;
  w69 = w69 + w70;
  w70 = w59 * w44;
  w69 = w69 + w70;
  w70 = w69 * w60;
  w71 = w40 * w62;
  w72 = w64 * w43;
  w71 = w71 + w72;
  w72 = w65 * w44;
  w71 = w71 + w72;
  w72 = w71 * w66;
  w70 = w70 + w72;
  w70 = w70 * w67;
  w68 = w68 + w70;
  w71 = w71 * w60;
  w69 = w69 * w66;
  w71 = w71 - w69;
  w71 = w71 * w57;
  w68 = w68 + w71;
  w71 = w40 * w63;
  w43 = w43 * w55;
  w71 = w71 + w43;
  w44 = w44 * w28;
  w71 = w71 + w44;
  w44 = w71 + w46;
  w44 = w68 + w44;
  w45 = w44 - w45;
  w43 = w13 * w45;
  w54 = w54 - w43;
  res0[11] = w54;
  w54 = w2 * w16;
  w43 = w12 * w18;
  w54 = w54 - w43;
  res0[12] = w54;
  w54 = w2 * w38;
  w43 = w12 * w47;
  w54 = w54 - w43;
  res0[13] = w54;
  w54 = w2 * w36;
  w43 = w12 * w45;
  w54 = w54 - w43;
  res0[14] = w54;
  w54 = w1 * w16;
  w43 = w5 * w18;
  w54 = w54 - w43;
  res0[15] = w54;
  w38 = w1 * w38;
  w47 = w5 * w47;
  w38 = w38 - w47;
  res0[16] = w38;
  w36 = w1 * w36;
  w45 = w5 * w45;
  w36 = w36 - w45;
  res0[17] = w36;
  w36 = 0.0;
  res0[18] = w36;
  w45 = w40 * w20;
  w38 = w8 * w41;
  w45 = w45 - w38;
  res0[19] = w45;
  w30 = w30 - w37;
  w30 = w40 * w30;
  w44 = w44 - w46;
  w44 = w8 * w44;
  w30 = w30 - w44;
  res0[20] = w30;
  res0[21] = w36;
  res0[22] = w36;
  w36 = w61 * w53;
  w30 = w48 * w68;
  w36 = w36 - w30;
  res0[23] = w36;
  w36 = arg1[3];
  w30 = w11 * w36;
  w44 = arg1[4];
  w46 = w2 * w44;
  w30 = w30 + w46;
  w46 = arg1[5];
  w37 = w1 * w46;
  w30 = w30 + w37;
  w37 = arg1[0];
  w45 = w13 * w37;
  w38 = arg1[1];
  w47 = w12 * w38;
  w45 = w45 + w47;
  w47 = arg1[2];
  w54 = w5 * w47;
  w45 = w45 + w54;
  w45 = w30 * w45;
  w13 = w13 * w36;
  w12 = w12 * w44;
  w13 = w13 + w12;
  w5 = w5 * w46;
  w13 = w13 + w5;
  w11 = w11 * w37;
  w2 = w2 * w38;
  w11 = w11 + w2;
  w1 = w1 * w47;
  w11 = w11 + w1;
  w11 = w13 * w11;
  w45 = w45 - w11;
  w36 = w4 * w36;
  w44 = w9 * w44;
  w36 = w36 + w44;
  w46 = w14 * w46;
  w36 = w36 + w46;
  w18 = w18 * w36;
  w15 = w4 * w15;
  w0 = w9 * w0;
  w15 = w15 + w0;
  w10 = w14 * w10;
  w15 = w15 + w10;
  w10 = w15 * w30;
  w18 = w18 - w10;
  w18 = w18 * w30;
  w18 = w45 + w18;
  w10 = w15 * w13;
  w16 = w16 * w36;
  w10 = w10 - w16;
  w10 = w10 * w13;
  w18 = w18 - w10;
  res1[0] = w18;
  w42 = w42 * w36;
  w19 = w4 * w19;
  w21 = w9 * w21;
  w19 = w19 + w21;
  w35 = w14 * w35;
  w19 = w19 + w35;
  w35 = w19 * w30;
  w42 = w42 - w35;
  w42 = w30 * w42;
  w45 = w45 + w42;
  w42 = w19 * w13;
  w22 = w22 * w36;
  w42 = w42 - w22;
  w42 = w13 * w42;
  w45 = w45 - w42;
  w42 = arg1[6];
  w17 = w17 * w4;
  w3 = w3 * w9;
  w17 = w17 + w3;
  w6 = w6 * w14;
  w17 = w17 + w6;
  w6 = w17 * w13;
  w3 = w8 * w36;
  w6 = w6 - w3;
  w6 = w42 * w6;
  w3 = w6 * w20;
  w3 = w45 + w3;
  w22 = w17 * w42;
  w22 = w36 + w22;
  w35 = w41 * w22;
  w7 = w17 * w7;
  w23 = w23 * w4;
  w25 = w25 * w9;
  w23 = w23 + w25;
  w26 = w26 * w14;
  w23 = w23 + w26;
  w26 = w23 * w27;
  w29 = w29 * w4;
  w31 = w31 * w9;
  w29 = w29 + w31;
  w32 = w32 * w14;
  w29 = w29 + w32;
  w32 = w29 * w33;
  w26 = w26 + w32;
  w34 = w26 * w34;
  w7 = w7 + w34;
  w29 = w29 * w27;
  w23 = w23 * w33;
  w29 = w29 - w23;
  w24 = w29 * w24;
  w7 = w7 + w24;
  w24 = w40 * w42;
  w24 = w30 + w24;
  w23 = w7 * w24;
  w35 = w35 - w23;
  w35 = w35 * w24;
  w3 = w3 + w35;
  w40 = w40 * w36;
  w30 = w17 * w30;
  w40 = w40 - w30;
  w40 = w42 * w40;
  w41 = w40 * w41;
  w3 = w3 - w41;
  w8 = w8 * w42;
  w13 = w13 + w8;
  w8 = w7 * w13;
  w20 = w20 * w22;
  w8 = w8 - w20;
  w8 = w8 * w13;
  w3 = w3 - w8;
  res1[1] = w3;
  w3 = w6 * w52;
  w45 = w45 + w3;
  w3 = w71 * w22;
  w63 = w17 * w63;
  w55 = w26 * w55;
  w63 = w63 + w55;
  w28 = w29 * w28;
  w63 = w63 + w28;
  w28 = w63 * w24;
  w3 = w3 - w28;
  w3 = w24 * w3;
  w45 = w45 + w3;
  w71 = w40 * w71;
  w45 = w45 - w71;
  w71 = w63 * w13;
  w52 = w52 * w22;
  w71 = w71 - w52;
  w71 = w13 * w71;
  w45 = w45 - w71;
  w71 = arg1[7];
  w39 = w17 * w39;
  w49 = w49 * w26;
  w39 = w39 + w49;
  w50 = w50 * w29;
  w39 = w39 + w50;
  w50 = w39 * w13;
  w49 = w48 * w22;
  w50 = w50 - w49;
  w50 = w71 * w50;
  w6 = w6 + w50;
  w6 = w6 * w53;
  w45 = w45 + w6;
  w6 = w39 * w71;
  w6 = w22 + w6;
  w50 = w68 * w6;
  w51 = w39 * w51;
  w56 = w17 * w56;
  w58 = w58 * w26;
  w56 = w56 + w58;
  w59 = w59 * w29;
  w56 = w56 + w59;
  w59 = w56 * w60;
  w17 = w17 * w62;
  w64 = w64 * w26;
  w17 = w17 + w64;
  w65 = w65 * w29;
  w17 = w17 + w65;
  w65 = w17 * w66;
  w59 = w59 + w65;
  w59 = w59 * w67;
  w51 = w51 + w59;
  w17 = w17 * w60;
  w56 = w56 * w66;
  w17 = w17 - w56;
  w17 = w17 * w57;
  w51 = w51 + w17;
  w17 = w61 * w71;
  w17 = w24 + w17;
  w57 = w51 * w17;
  w50 = w50 - w57;
  w50 = w50 * w17;
  w45 = w45 + w50;
  w61 = w61 * w22;
  w39 = w39 * w24;
  w61 = w61 - w39;
  w61 = w71 * w61;
  w40 = w40 + w61;
  w40 = w40 * w68;
  w45 = w45 - w40;
  w48 = w48 * w71;
  w13 = w13 + w48;
  w48 = w51 * w13;
  w53 = w53 * w6;
  w48 = w48 - w53;
  w48 = w48 * w13;
  w45 = w45 - w48;
  res1[2] = w45;
  w45 = arg0[2];
  w15 = w15 + w45;
  res2[0] = w15;
  w19 = w19 + w45;
  w7 = w7 + w19;
  res2[1] = w7;
  w63 = w63 + w19;
  w51 = w51 + w63;
  res2[2] = w51;
}


CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_ground_rows(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[3];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 74);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 3; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && res[0] && res[1] && res[2]) {
    /* cos and sin of q[7..8] of 16 samples at a time, then snakecg_sp2_ground_rows_sincos
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
        snakecg_sp2_ground_rows_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], ca + i * na, sa + i * na, res[0] + (i0 + i) * 24, res[1] + (i0 + i) * 3, res[2] + (i0 + i) * 3);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      a[2] = arg[2] + i * stride[2];
      a[3] = arg[3] + i * stride[3];
      r[0] = res[0] + i * 24;
      r[1] = res[1] + i * 3;
      r[2] = res[2] + i * 3;
      if (snakecg_sp2_ground_rows(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
