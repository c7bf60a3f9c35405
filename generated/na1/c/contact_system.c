/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for contact_system() of
 * generated/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 69ac8a580508aa26bce28f4a88e0f77c0b28e33b1f2694eb6cf4bbbcae64a5df
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na1_contact_system_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {4, 1, 1};
static const casadi_int casadi_s1[3] = {1, 1, 1};
static const casadi_int casadi_s2[3] = {3, 1, 1};
static const casadi_int casadi_s3[3] = {16, 1, 1};
static const casadi_int casadi_s4[3] = {2, 1, 1};
static const casadi_int casadi_s5[3] = {4, 4, 1};
static const casadi_int casadi_s6[3] = {3, 3, 1};
static const casadi_int casadi_s7[3] = {4, 3, 1};

/* snakecg_na1_contact_system:(q[4],v[4],tau,q_obj[3],v_obj[3],f_obj[3],K[16],contact_link[2],side,object_mass,object_inertia,rho[2],wheel_offset[2])->(M[4x4],delassus[3x3],b[3],qdd_free[4],a_obj_free[3],qdd_from_lam[4x3],a_obj_from_lam[3x3],gap,s) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73;
  a00=arg[6]? arg[6][8] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=0.;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[6]? arg[6][10] : 0;
  a03=arg[0]? arg[0][3] : 0;
  a04=arg[0]? arg[0][2] : 0;
  a03=(a03+a04);
  a05=sin(a03);
  a06=(a02*a05);
  a07=arg[6]? arg[6][9] : 0;
  a08=sin(a04);
  a09=(a07*a08);
  a09=(a06+a09);
  a10=(-a09);
  if (res[0]!=0) res[0][2]=a10;
  a11=(-a06);
  if (res[0]!=0) res[0][3]=a11;
  if (res[0]!=0) res[0][4]=a01;
  if (res[0]!=0) res[0][5]=a00;
  a12=cos(a03);
  a02=(a02*a12);
  a13=cos(a04);
  a07=(a07*a13);
  a07=(a02+a07);
  if (res[0]!=0) res[0][6]=a07;
  if (res[0]!=0) res[0][7]=a02;
  if (res[0]!=0) res[0][8]=a10;
  if (res[0]!=0) res[0][9]=a07;
  a10=(a13*a12);
  a14=(a08*a05);
  a10=(a10+a14);
  a14=arg[6]? arg[6][12] : 0;
  a10=(a10*a14);
  a14=arg[6]? arg[6][14] : 0;
  a14=(a10+a14);
  a15=arg[6]? arg[6][15] : 0;
  a10=(a10+a15);
  a14=(a14+a10);
  if (res[0]!=0) res[0][10]=a14;
  if (res[0]!=0) res[0][11]=a10;
  if (res[0]!=0) res[0][12]=a11;
  if (res[0]!=0) res[0][13]=a02;
  if (res[0]!=0) res[0][14]=a10;
  if (res[0]!=0) res[0][15]=a15;
  a11=arg[7]? arg[7][0] : 0;
  a04=(a04*a11);
  a16=arg[7]? arg[7][1] : 0;
  a03=(a03*a16);
  a04=(a04+a03);
  a03=sin(a04);
  a17=arg[8]? arg[8][0] : 0;
  a18=(a03*a17);
  a19=(a11+a16);
  a20=(a18*a19);
  a21=(a20/a00);
  a09=(a09/a00);
  a22=arg[0]? arg[0][1] : 0;
  a23=arg[6]? arg[6][2] : 0;
  a24=arg[6]? arg[6][6] : 0;
  a23=(a23-a24);
  a25=(a23*a08);
  a26=(a22+a25);
  a27=arg[6]? arg[6][7] : 0;
  a28=(a05*a27);
  a26=(a26+a28);
  a29=(a22-a26);
  a30=(a16*a29);
  a31=(a18*a30);
  a04=cos(a04);
  a32=(a04*a17);
  a33=arg[0]? arg[0][0] : 0;
  a34=(a13*a23);
  a35=(a33+a34);
  a36=(a12*a27);
  a35=(a35+a36);
  a37=(a35-a33);
  a38=(a16*a37);
  a39=(a32*a38);
  a31=(a31-a39);
  a24=(a24*a11);
  a39=(a27*a16);
  a24=(a24+a39);
  a39=(a17*a24);
  a40=arg[3]? arg[3][2] : 0;
  a41=cos(a40);
  a42=arg[11]? arg[11][1] : 0;
  a43=(a41*a42);
  a40=sin(a40);
  a44=arg[11]? arg[11][0] : 0;
  a45=(a40*a44);
  a43=(a43+a45);
  a45=arg[3]? arg[3][1] : 0;
  a45=(a43+a45);
  a46=(a03*a24);
  a45=(a45+a46);
  a46=(a22*a11);
  a26=(a26*a16);
  a46=(a46+a26);
  a45=(a45-a46);
  a46=(a18*a45);
  a39=(a39-a46);
  a41=(a41*a44);
  a40=(a40*a42);
  a41=(a41-a40);
  a40=arg[3]? arg[3][0] : 0;
  a40=(a41+a40);
  a24=(a04*a24);
  a40=(a40+a24);
  a11=(a33*a11);
  a35=(a35*a16);
  a11=(a11+a35);
  a40=(a40-a11);
  a11=(a32*a40);
  a39=(a39-a11);
  a11=(a39*a19);
  a31=(a31+a11);
  a11=(a09*a20);
  a11=(a31+a11);
  a07=(a07/a00);
  a35=(a32*a19);
  a24=(a07*a35);
  a11=(a11+a24);
  a24=casadi_sq(a09);
  a24=(a24*a00);
  a14=(a14-a24);
  a24=casadi_sq(a07);
  a24=(a24*a00);
  a14=(a14-a24);
  a24=(a11/a14);
  a06=(a06/a00);
  a42=(a06*a09);
  a42=(a42*a00);
  a10=(a10-a42);
  a02=(a02/a00);
  a42=(a02*a07);
  a42=(a42*a00);
  a10=(a10-a42);
  a10=(a10/a14);
  a39=(a39*a16);
  a42=(a16*a28);
  a44=(a18*a42);
  a46=(a16*a36);
  a26=(a32*a46);
  a44=(a44+a26);
  a39=(a39-a44);
  a44=(a06*a20);
  a44=(a39+a44);
  a26=(a02*a35);
  a44=(a44+a26);
  a11=(a10*a11);
  a44=(a44-a11);
  a11=casadi_sq(a06);
  a11=(a11*a00);
  a15=(a15-a11);
  a11=casadi_sq(a02);
  a11=(a11*a00);
  a15=(a15-a11);
  a11=casadi_sq(a10);
  a11=(a11*a14);
  a15=(a15-a11);
  a44=(a44/a15);
  a11=(a10*a44);
  a24=(a24-a11);
  a11=(a09*a24);
  a21=(a21+a11);
  a11=(a06*a44);
  a21=(a21+a11);
  a11=(a20*a21);
  a26=(a35/a00);
  a47=(a07*a24);
  a26=(a26+a47);
  a47=(a02*a44);
  a26=(a26+a47);
  a47=(a35*a26);
  a11=(a11+a47);
  a47=(a31*a24);
  a11=(a11+a47);
  a47=(a39*a44);
  a11=(a11+a47);
  a47=arg[9]? arg[9][0] : 0;
  a48=(a18/a47);
  a49=(a18*a48);
  a50=(a32/a47);
  a51=(a32*a50);
  a49=(a49+a51);
  a51=(a04*a41);
  a51=(a51*a17);
  a52=(a18*a43);
  a51=(a51+a52);
  a52=arg[10]? arg[10][0] : 0;
  a53=(a51/a52);
  a54=(a51*a53);
  a49=(a49+a54);
  a11=(a11+a49);
  if (res[1]!=0) res[1][0]=a11;
  a11=arg[12]? arg[12][0] : 0;
  a49=(a11*a24);
  a54=(a08*a21);
  a55=(a13*a26);
  a54=(a54+a55);
  a49=(a49-a54);
  if (res[1]!=0) res[1][1]=a49;
  a49=(a12*a37);
  a54=(a05*a29);
  a49=(a49-a54);
  a54=arg[12]? arg[12][1] : 0;
  a49=(a49+a54);
  a55=(a49*a24);
  a56=(a05*a21);
  a57=(a12*a26);
  a56=(a56+a57);
  a55=(a55-a56);
  a56=(a05*a28);
  a57=(a12*a36);
  a56=(a56+a57);
  a56=(a56+a54);
  a54=(a56*a44);
  a55=(a55+a54);
  if (res[1]!=0) res[1][2]=a55;
  a55=(a09*a08);
  a55=(a11-a55);
  a54=(a07*a13);
  a55=(a55-a54);
  a54=(a55/a14);
  a57=(a06*a08);
  a58=(a02*a13);
  a57=(a57+a58);
  a55=(a10*a55);
  a57=(a57+a55);
  a57=(a57/a15);
  a55=(a10*a57);
  a54=(a54+a55);
  a55=(a09*a54);
  a58=(a08/a00);
  a55=(a55-a58);
  a58=(a06*a57);
  a55=(a55-a58);
  a58=(a20*a55);
  a59=(a13/a00);
  a60=(a07*a54);
  a59=(a59-a60);
  a60=(a02*a57);
  a59=(a59+a60);
  a60=(a35*a59);
  a58=(a58-a60);
  a60=(a31*a54);
  a58=(a58+a60);
  a60=(a39*a57);
  a58=(a58-a60);
  if (res[1]!=0) res[1][3]=a58;
  a58=(a13*a59);
  a60=(a08*a55);
  a58=(a58-a60);
  a60=(a11*a54);
  a58=(a58+a60);
  if (res[1]!=0) res[1][4]=a58;
  a58=(a12*a59);
  a60=(a05*a55);
  a58=(a58-a60);
  a60=(a49*a54);
  a58=(a58+a60);
  a60=(a56*a57);
  a58=(a58-a60);
  if (res[1]!=0) res[1][5]=a58;
  a58=(a09*a05);
  a58=(a49-a58);
  a60=(a07*a12);
  a58=(a58-a60);
  a60=(a58/a14);
  a61=(a06*a05);
  a61=(a56-a61);
  a62=(a02*a12);
  a61=(a61-a62);
  a58=(a10*a58);
  a61=(a61-a58);
  a61=(a61/a15);
  a58=(a10*a61);
  a60=(a60-a58);
  a58=(a09*a60);
  a62=(a05/a00);
  a58=(a58-a62);
  a62=(a06*a61);
  a58=(a58+a62);
  a62=(a20*a58);
  a63=(a12/a00);
  a64=(a07*a60);
  a63=(a63-a64);
  a64=(a02*a61);
  a63=(a63-a64);
  a64=(a35*a63);
  a62=(a62-a64);
  a64=(a31*a60);
  a62=(a62+a64);
  a64=(a39*a61);
  a62=(a62+a64);
  if (res[1]!=0) res[1][6]=a62;
  a62=(a13*a63);
  a64=(a08*a58);
  a62=(a62-a64);
  a64=(a11*a60);
  a62=(a62+a64);
  if (res[1]!=0) res[1][7]=a62;
  a62=(a12*a63);
  a64=(a05*a58);
  a62=(a62-a64);
  a64=(a49*a60);
  a62=(a62+a64);
  a64=(a56*a61);
  a62=(a62+a64);
  if (res[1]!=0) res[1][8]=a62;
  a62=arg[1]? arg[1][2] : 0;
  a64=casadi_sq(a62);
  a65=(a64*a34);
  a66=arg[1]? arg[1][3] : 0;
  a67=(a66+a62);
  a67=casadi_sq(a67);
  a68=(a67*a36);
  a65=(a65+a68);
  a68=arg[6]? arg[6][1] : 0;
  a65=(a65*a68);
  a69=(a65/a00);
  a70=(a09*a65);
  a71=(a25+a22);
  a72=(a28+a71);
  a72=(a65*a72);
  a25=(a64*a25);
  a73=(a67*a28);
  a25=(a25+a73);
  a34=(a34+a33);
  a73=(a36+a34);
  a73=(a25*a73);
  a73=(a73*a68);
  a72=(a72-a73);
  a22=(a65*a22);
  a22=(a72-a22);
  a25=(a25*a68);
  a33=(a25*a33);
  a22=(a22+a33);
  a70=(a70-a22);
  a22=(a07*a25);
  a70=(a70-a22);
  a14=(a70/a14);
  a22=arg[2]? arg[2][0] : 0;
  a71=(a65*a71);
  a72=(a72-a71);
  a34=(a25*a34);
  a72=(a72+a34);
  a22=(a22-a72);
  a65=(a06*a65);
  a22=(a22+a65);
  a65=(a02*a25);
  a22=(a22-a65);
  a70=(a10*a70);
  a22=(a22-a70);
  a22=(a22/a15);
  a10=(a10*a22);
  a14=(a14-a10);
  a09=(a09*a14);
  a69=(a69+a09);
  a06=(a06*a22);
  a69=(a69+a06);
  a20=(a20*a69);
  a25=(a25/a00);
  a07=(a07*a14);
  a25=(a25-a07);
  a02=(a02*a22);
  a25=(a25-a02);
  a35=(a35*a25);
  a20=(a20-a35);
  a31=(a31*a14);
  a20=(a20+a31);
  a39=(a39*a22);
  a20=(a20+a39);
  a39=arg[5]? arg[5][1] : 0;
  a39=(a39/a47);
  a31=(a32*a39);
  a35=arg[5]? arg[5][0] : 0;
  a35=(a35/a47);
  a47=(a18*a35);
  a31=(a31-a47);
  a47=arg[5]? arg[5][2] : 0;
  a47=(a47/a52);
  a51=(a51*a47);
  a31=(a31+a51);
  a20=(a20+a31);
  a31=arg[1]? arg[1][0] : 0;
  a51=(a19*a31);
  a30=(a30*a62);
  a51=(a51+a30);
  a42=(a42*a66);
  a51=(a51-a42);
  a51=(a32*a51);
  a42=(a19*a62);
  a30=(a16*a66);
  a42=(a42+a30);
  a30=(a51*a42);
  a64=(a64*a23);
  a23=(a13*a64);
  a27=(a27*a67);
  a67=(a12*a27);
  a23=(a23+a67);
  a67=(a23*a16);
  a67=(a18*a67);
  a30=(a30-a67);
  a67=arg[1]? arg[1][1] : 0;
  a19=(a19*a67);
  a38=(a38*a62);
  a19=(a19+a38);
  a46=(a46*a66);
  a19=(a19+a46);
  a19=(a18*a19);
  a46=(a19*a42);
  a30=(a30+a46);
  a51=(a51+a19);
  a43=(a43*a32);
  a41=(a18*a41);
  a19=(a43-a41);
  a46=arg[4]? arg[4][2] : 0;
  a38=(a19*a46);
  a51=(a51+a38);
  a38=arg[4]? arg[4][0] : 0;
  a38=(a32*a38);
  a51=(a51-a38);
  a52=arg[4]? arg[4][1] : 0;
  a18=(a18*a52);
  a51=(a51-a18);
  a52=(a45*a32);
  a02=(a03*a40);
  a02=(a02*a17);
  a52=(a52-a02);
  a02=(a52*a42);
  a51=(a51-a02);
  a51=(a42*a51);
  a30=(a30+a51);
  a19=(a19*a42);
  a41=(a41-a43);
  a41=(a46*a41);
  a19=(a19+a41);
  a46=(a46*a19);
  a30=(a30+a46);
  a38=(a38*a42);
  a30=(a30-a38);
  a18=(a18*a42);
  a30=(a30-a18);
  a64=(a64*a08);
  a27=(a27*a05);
  a64=(a64+a27);
  a16=(a64*a16);
  a32=(a32*a16);
  a30=(a30+a32);
  a20=(a20+a30);
  if (res[2]!=0) res[2][0]=a20;
  a20=(a13*a25);
  a30=(a08*a69);
  a20=(a20-a30);
  a11=(a11*a14);
  a20=(a20+a11);
  a08=(a08*a67);
  a08=(a08*a62);
  a13=(a13*a31);
  a13=(a13*a62);
  a08=(a08+a13);
  a20=(a20-a08);
  if (res[2]!=0) res[2][1]=a20;
  a20=(a12*a25);
  a08=(a05*a69);
  a20=(a20-a08);
  a49=(a49*a14);
  a20=(a20+a49);
  a56=(a56*a22);
  a20=(a20+a56);
  a23=(a05*a23);
  a64=(a12*a64);
  a23=(a23-a64);
  a37=(a37*a62);
  a67=(a67+a37);
  a36=(a36*a66);
  a67=(a67+a36);
  a05=(a05*a67);
  a67=(a62+a66);
  a05=(a05*a67);
  a23=(a23-a05);
  a29=(a29*a62);
  a31=(a31+a29);
  a28=(a28*a66);
  a31=(a31-a28);
  a12=(a12*a31);
  a12=(a12*a67);
  a23=(a23-a12);
  a20=(a20+a23);
  if (res[2]!=0) res[2][2]=a20;
  if (res[3]!=0) res[3][0]=a69;
  if (res[3]!=0) res[3][1]=a25;
  if (res[3]!=0) res[3][2]=a14;
  if (res[3]!=0) res[3][3]=a22;
  if (res[4]!=0) res[4][0]=a35;
  if (res[4]!=0) res[4][1]=a39;
  if (res[4]!=0) res[4][2]=a47;
  if (res[5]!=0) res[5][0]=a21;
  a26=(-a26);
  if (res[5]!=0) res[5][1]=a26;
  if (res[5]!=0) res[5][2]=a24;
  if (res[5]!=0) res[5][3]=a44;
  if (res[5]!=0) res[5][4]=a55;
  if (res[5]!=0) res[5][5]=a59;
  if (res[5]!=0) res[5][6]=a54;
  a57=(-a57);
  if (res[5]!=0) res[5][7]=a57;
  if (res[5]!=0) res[5][8]=a58;
  if (res[5]!=0) res[5][9]=a63;
  if (res[5]!=0) res[5][10]=a60;
  if (res[5]!=0) res[5][11]=a61;
  a48=(-a48);
  if (res[6]!=0) res[6][0]=a48;
  if (res[6]!=0) res[6][1]=a50;
  if (res[6]!=0) res[6][2]=a53;
  if (res[6]!=0) res[6][3]=a01;
  if (res[6]!=0) res[6][4]=a01;
  if (res[6]!=0) res[6][5]=a01;
  if (res[6]!=0) res[6][6]=a01;
  if (res[6]!=0) res[6][7]=a01;
  if (res[6]!=0) res[6][8]=a01;
  if (res[7]!=0) res[7][0]=a52;
  a03=(a03*a45);
  a04=(a04*a40);
  a03=(a03+a04);
  if (res[8]!=0) res[8][0]=a03;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na1_contact_system_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_contact_system_n_in(void) { return 13;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na1_contact_system_n_out(void) { return 9;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na1_contact_system_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_contact_system_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "tau";
    case 3: return "q_obj";
    case 4: return "v_obj";
    case 5: return "f_obj";
    case 6: return "K";
    case 7: return "contact_link";
    case 8: return "side";
    case 9: return "object_mass";
    case 10: return "object_inertia";
    case 11: return "rho";
    case 12: return "wheel_offset";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na1_contact_system_name_out(casadi_int i) {
  switch (i) {
    case 0: return "M";
    case 1: return "delassus";
    case 2: return "b";
    case 3: return "qdd_free";
    case 4: return "a_obj_free";
    case 5: return "qdd_from_lam";
    case 6: return "a_obj_from_lam";
    case 7: return "gap";
    case 8: return "s";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_contact_system_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s0;
    case 2: return casadi_s1;
    case 3: return casadi_s2;
    case 4: return casadi_s2;
    case 5: return casadi_s2;
    case 6: return casadi_s3;
    case 7: return casadi_s4;
    case 8: return casadi_s1;
    case 9: return casadi_s1;
    case 10: return casadi_s1;
    case 11: return casadi_s4;
    case 12: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na1_contact_system_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s5;
    case 1: return casadi_s6;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    case 4: return casadi_s2;
    case 5: return casadi_s7;
    case 6: return casadi_s6;
    case 7: return casadi_s1;
    case 8: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13;
  if (sz_res) *sz_res = 9;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na1_contact_system_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 13*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 9*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na1_batch_contact_system(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[13];
  casadi_real* r[9];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 75);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 13; ++k) a[k] = 0;
  for (k = 0; k < 9; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    a[7] = arg[7] + i * stride[7];
    a[8] = arg[8] + i * stride[8];
    a[9] = arg[9] + i * stride[9];
    a[10] = arg[10] + i * stride[10];
    a[11] = arg[11] + i * stride[11];
    a[12] = arg[12] + i * stride[12];
    r[0] = res[0] + i * 16;
    r[1] = res[1] + i * 9;
    r[2] = res[2] + i * 3;
    r[3] = res[3] + i * 4;
    r[4] = res[4] + i * 3;
    r[5] = res[5] + i * 12;
    r[6] = res[6] + i * 9;
    r[7] = res[7] + i * 1;
    r[8] = res[8] + i * 1;
    if (snakecg_na1_contact_system(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
