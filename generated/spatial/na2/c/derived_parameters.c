/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for derived_parameters() of
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
  #define CASADI_PREFIX(ID) snakecg_sp2_derived_parameters_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp2_derived_parameters_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_derived_parameters_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_derived_parameters_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {3, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {18, 1, 1};
static const casadi_int casadi_s3[3] = {6, 1, 1};
static const casadi_int casadi_s4[3] = {120, 1, 1};

/* snakecg_sp2_derived_parameters:(link_mass[3],link_com[9],link_inertia[18],joint_xyz[6],joint_rpy[6],joint_axis[6],gravity[3])->(K[120]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a00;
  a00=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][3]=a00;
  a01=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][4]=a01;
  a02=arg[1]? arg[1][2] : 0;
  if (res[0]!=0) res[0][5]=a02;
  a03=arg[1]? arg[1][3] : 0;
  if (res[0]!=0) res[0][6]=a03;
  a04=arg[1]? arg[1][4] : 0;
  if (res[0]!=0) res[0][7]=a04;
  a05=arg[1]? arg[1][5] : 0;
  if (res[0]!=0) res[0][8]=a05;
  a06=arg[1]? arg[1][6] : 0;
  if (res[0]!=0) res[0][9]=a06;
  a07=arg[1]? arg[1][7] : 0;
  if (res[0]!=0) res[0][10]=a07;
  a08=arg[1]? arg[1][8] : 0;
  if (res[0]!=0) res[0][11]=a08;
  a09=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][12]=a09;
  a10=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][13]=a10;
  a11=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][14]=a11;
  a12=arg[2]? arg[2][3] : 0;
  if (res[0]!=0) res[0][15]=a12;
  a13=arg[2]? arg[2][4] : 0;
  if (res[0]!=0) res[0][16]=a13;
  a14=arg[2]? arg[2][5] : 0;
  if (res[0]!=0) res[0][17]=a14;
  a15=arg[2]? arg[2][6] : 0;
  if (res[0]!=0) res[0][18]=a15;
  a16=arg[2]? arg[2][7] : 0;
  if (res[0]!=0) res[0][19]=a16;
  a17=arg[2]? arg[2][8] : 0;
  if (res[0]!=0) res[0][20]=a17;
  a18=arg[2]? arg[2][9] : 0;
  if (res[0]!=0) res[0][21]=a18;
  a19=arg[2]? arg[2][10] : 0;
  if (res[0]!=0) res[0][22]=a19;
  a20=arg[2]? arg[2][11] : 0;
  if (res[0]!=0) res[0][23]=a20;
  a21=arg[2]? arg[2][12] : 0;
  if (res[0]!=0) res[0][24]=a21;
  a22=arg[2]? arg[2][13] : 0;
  if (res[0]!=0) res[0][25]=a22;
  a23=arg[2]? arg[2][14] : 0;
  if (res[0]!=0) res[0][26]=a23;
  a24=arg[2]? arg[2][15] : 0;
  if (res[0]!=0) res[0][27]=a24;
  a25=arg[2]? arg[2][16] : 0;
  if (res[0]!=0) res[0][28]=a25;
  a26=arg[2]? arg[2][17] : 0;
  if (res[0]!=0) res[0][29]=a26;
  a27=arg[3]? arg[3][0] : 0;
  if (res[0]!=0) res[0][30]=a27;
  a28=arg[3]? arg[3][1] : 0;
  if (res[0]!=0) res[0][31]=a28;
  a29=arg[3]? arg[3][2] : 0;
  if (res[0]!=0) res[0][32]=a29;
  a30=arg[3]? arg[3][3] : 0;
  if (res[0]!=0) res[0][33]=a30;
  a31=arg[3]? arg[3][4] : 0;
  if (res[0]!=0) res[0][34]=a31;
  a32=arg[3]? arg[3][5] : 0;
  if (res[0]!=0) res[0][35]=a32;
  a33=arg[4]? arg[4][0] : 0;
  if (res[0]!=0) res[0][36]=a33;
  a34=arg[4]? arg[4][1] : 0;
  if (res[0]!=0) res[0][37]=a34;
  a35=arg[4]? arg[4][2] : 0;
  if (res[0]!=0) res[0][38]=a35;
  a36=arg[4]? arg[4][3] : 0;
  if (res[0]!=0) res[0][39]=a36;
  a37=arg[4]? arg[4][4] : 0;
  if (res[0]!=0) res[0][40]=a37;
  a38=arg[4]? arg[4][5] : 0;
  if (res[0]!=0) res[0][41]=a38;
  a39=arg[5]? arg[5][0] : 0;
  if (res[0]!=0) res[0][42]=a39;
  a40=arg[5]? arg[5][1] : 0;
  if (res[0]!=0) res[0][43]=a40;
  a41=arg[5]? arg[5][2] : 0;
  if (res[0]!=0) res[0][44]=a41;
  a42=arg[5]? arg[5][3] : 0;
  if (res[0]!=0) res[0][45]=a42;
  a43=arg[5]? arg[5][4] : 0;
  if (res[0]!=0) res[0][46]=a43;
  a44=arg[5]? arg[5][5] : 0;
  if (res[0]!=0) res[0][47]=a44;
  a45=arg[6]? arg[6][0] : 0;
  if (res[0]!=0) res[0][48]=a45;
  a45=arg[6]? arg[6][1] : 0;
  if (res[0]!=0) res[0][49]=a45;
  a45=arg[6]? arg[6][2] : 0;
  if (res[0]!=0) res[0][50]=a45;
  a45=0.;
  a46=casadi_sq(a39);
  a47=casadi_sq(a40);
  a46=(a46+a47);
  a47=casadi_sq(a41);
  a46=(a46+a47);
  a47=-5.0000000000000000e-01;
  a46=pow(a46,a47);
  a41=(a41*a46);
  a48=(a45<=a41);
  a49=1.;
  a39=(a39*a46);
  a50=casadi_sq(a39);
  a51=(a49+a41);
  a52=(a50/a51);
  a52=(a49-a52);
  a52=(a48?a52:0);
  a53=(!a48);
  a54=(a49-a41);
  a50=(a50/a54);
  a50=(a49-a50);
  a50=(a53?a50:0);
  a52=(a52+a50);
  a50=5.0000000000000000e-01;
  a55=casadi_sq(a52);
  a55=(a15*a55);
  a40=(a40*a46);
  a46=(a39*a40);
  a56=(a46/a51);
  a56=(-a56);
  a56=(a48?a56:0);
  a46=(a46/a54);
  a57=(-a46);
  a57=(a53?a57:0);
  a57=(a56+a57);
  a58=casadi_sq(a57);
  a58=(a16*a58);
  a55=(a55+a58);
  a58=(-a39);
  a58=(a48?a58:0);
  a59=(a53?a39:0);
  a58=(a58+a59);
  a59=casadi_sq(a58);
  a59=(a17*a59);
  a55=(a55+a59);
  a59=-2.;
  a60=(a59*a18);
  a46=(a53?a46:0);
  a56=(a56+a46);
  a60=(a60*a56);
  a46=casadi_sq(a40);
  a51=(a46/a51);
  a51=(a49-a51);
  a48=(a48?a51:0);
  a54=(a46/a54);
  a54=(a54-a49);
  a53=(a53?a54:0);
  a48=(a48+a53);
  a60=(a60*a48);
  a55=(a55+a60);
  a60=(2.*a18);
  a53=(a60*a52);
  a54=(a53*a57);
  a55=(a55+a54);
  a54=(2.*a19);
  a51=(a54*a52);
  a51=(a51*a58);
  a55=(a55+a51);
  a54=(a54*a56);
  a51=(a54*a40);
  a55=(a55+a51);
  a51=(2.*a20);
  a61=(a51*a57);
  a61=(a61*a58);
  a55=(a55+a61);
  a51=(a51*a48);
  a61=(a51*a40);
  a55=(a55+a61);
  a61=casadi_sq(a56);
  a61=(a15*a61);
  a55=(a55-a61);
  a61=casadi_sq(a48);
  a61=(a16*a61);
  a55=(a55-a61);
  a46=(a17*a46);
  a55=(a55-a46);
  a46=casadi_sq(a55);
  a61=(a59*a19);
  a61=(a61*a52);
  a61=(a61*a40);
  a62=(a59*a20);
  a62=(a62*a57);
  a62=(a62*a40);
  a61=(a61+a62);
  a62=(a59*a17);
  a62=(a62*a58);
  a62=(a62*a40);
  a61=(a61+a62);
  a62=(2.*a15);
  a62=(a62*a52);
  a62=(a62*a56);
  a61=(a61+a62);
  a53=(a53*a48);
  a61=(a61+a53);
  a60=(a60*a56);
  a60=(a60*a57);
  a61=(a61+a60);
  a54=(a54*a58);
  a61=(a61+a54);
  a54=(2.*a16);
  a54=(a54*a57);
  a54=(a54*a48);
  a61=(a61+a54);
  a51=(a51*a58);
  a61=(a61+a51);
  a51=casadi_sq(a61);
  a46=(a46+a51);
  a46=sqrt(a46);
  a51=(a45<a46);
  a54=(a45<=a55);
  a60=(a54?a55:0);
  a53=(!a54);
  a55=(-a55);
  a55=(a53?a55:0);
  a60=(a60+a55);
  a60=(a60/a46);
  a60=(a51?a60:0);
  a55=(!a51);
  a55=(a55?a49:0);
  a60=(a60+a55);
  a60=(a50*a60);
  a60=(a50+a60);
  a60=sqrt(a60);
  a55=(a52*a60);
  a54=(a54?a61:0);
  a61=(-a61);
  a53=(a53?a61:0);
  a54=(a54+a53);
  a54=(a54/a46);
  a54=(a50*a54);
  a54=(a54/a60);
  a46=(a56*a54);
  a46=(a51?a46:0);
  a55=(a55+a46);
  if (res[0]!=0) res[0][51]=a55;
  a46=(a57*a60);
  a53=(a48*a54);
  a53=(a51?a53:0);
  a46=(a46+a53);
  if (res[0]!=0) res[0][52]=a46;
  a53=(a58*a60);
  a61=(a40*a54);
  a61=(a51?a61:0);
  a53=(a53-a61);
  if (res[0]!=0) res[0][53]=a53;
  a56=(a56*a60);
  a52=(a52*a54);
  a52=(a51?a52:0);
  a56=(a56-a52);
  if (res[0]!=0) res[0][54]=a56;
  a48=(a48*a60);
  a57=(a57*a54);
  a57=(a51?a57:0);
  a48=(a48-a57);
  if (res[0]!=0) res[0][55]=a48;
  a58=(a58*a54);
  a51=(a51?a58:0);
  a60=(a40*a60);
  a51=(a51+a60);
  a60=(-a51);
  if (res[0]!=0) res[0][56]=a60;
  if (res[0]!=0) res[0][57]=a39;
  if (res[0]!=0) res[0][58]=a40;
  if (res[0]!=0) res[0][59]=a41;
  a60=casadi_sq(a42);
  a58=casadi_sq(a43);
  a60=(a60+a58);
  a58=casadi_sq(a44);
  a60=(a60+a58);
  a60=pow(a60,a47);
  a44=(a44*a60);
  a47=(a45<=a44);
  a42=(a42*a60);
  a58=casadi_sq(a42);
  a54=(a49+a44);
  a57=(a58/a54);
  a57=(a49-a57);
  a57=(a47?a57:0);
  a52=(!a47);
  a61=(a49-a44);
  a58=(a58/a61);
  a58=(a49-a58);
  a58=(a52?a58:0);
  a57=(a57+a58);
  a58=casadi_sq(a57);
  a58=(a21*a58);
  a43=(a43*a60);
  a60=(a42*a43);
  a62=(a60/a54);
  a62=(-a62);
  a62=(a47?a62:0);
  a60=(a60/a61);
  a63=(-a60);
  a63=(a52?a63:0);
  a63=(a62+a63);
  a64=casadi_sq(a63);
  a64=(a22*a64);
  a58=(a58+a64);
  a64=(-a42);
  a64=(a47?a64:0);
  a65=(a52?a42:0);
  a64=(a64+a65);
  a65=casadi_sq(a64);
  a65=(a23*a65);
  a58=(a58+a65);
  a65=(a59*a24);
  a60=(a52?a60:0);
  a62=(a62+a60);
  a65=(a65*a62);
  a60=casadi_sq(a43);
  a54=(a60/a54);
  a54=(a49-a54);
  a47=(a47?a54:0);
  a61=(a60/a61);
  a61=(a61-a49);
  a52=(a52?a61:0);
  a47=(a47+a52);
  a65=(a65*a47);
  a58=(a58+a65);
  a65=(2.*a24);
  a52=(a65*a57);
  a61=(a52*a63);
  a58=(a58+a61);
  a61=(2.*a25);
  a54=(a61*a57);
  a54=(a54*a64);
  a58=(a58+a54);
  a61=(a61*a62);
  a54=(a61*a43);
  a58=(a58+a54);
  a54=(2.*a26);
  a66=(a54*a63);
  a66=(a66*a64);
  a58=(a58+a66);
  a54=(a54*a47);
  a66=(a54*a43);
  a58=(a58+a66);
  a66=casadi_sq(a62);
  a66=(a21*a66);
  a58=(a58-a66);
  a66=casadi_sq(a47);
  a66=(a22*a66);
  a58=(a58-a66);
  a60=(a23*a60);
  a58=(a58-a60);
  a60=casadi_sq(a58);
  a66=(a59*a25);
  a66=(a66*a57);
  a66=(a66*a43);
  a67=(a59*a26);
  a67=(a67*a63);
  a67=(a67*a43);
  a66=(a66+a67);
  a59=(a59*a23);
  a59=(a59*a64);
  a59=(a59*a43);
  a66=(a66+a59);
  a59=(2.*a21);
  a59=(a59*a57);
  a59=(a59*a62);
  a66=(a66+a59);
  a52=(a52*a47);
  a66=(a66+a52);
  a65=(a65*a62);
  a65=(a65*a63);
  a66=(a66+a65);
  a61=(a61*a64);
  a66=(a66+a61);
  a61=(2.*a22);
  a61=(a61*a63);
  a61=(a61*a47);
  a66=(a66+a61);
  a54=(a54*a64);
  a66=(a66+a54);
  a54=casadi_sq(a66);
  a60=(a60+a54);
  a60=sqrt(a60);
  a54=(a45<a60);
  a45=(a45<=a58);
  a61=(a45?a58:0);
  a65=(!a45);
  a58=(-a58);
  a58=(a65?a58:0);
  a61=(a61+a58);
  a61=(a61/a60);
  a61=(a54?a61:0);
  a58=(!a54);
  a58=(a58?a49:0);
  a61=(a61+a58);
  a61=(a50*a61);
  a61=(a50+a61);
  a61=sqrt(a61);
  a58=(a57*a61);
  a45=(a45?a66:0);
  a66=(-a66);
  a65=(a65?a66:0);
  a45=(a45+a65);
  a45=(a45/a60);
  a50=(a50*a45);
  a50=(a50/a61);
  a45=(a62*a50);
  a45=(a54?a45:0);
  a58=(a58+a45);
  if (res[0]!=0) res[0][60]=a58;
  a45=(a63*a61);
  a60=(a47*a50);
  a60=(a54?a60:0);
  a45=(a45+a60);
  if (res[0]!=0) res[0][61]=a45;
  a60=(a64*a61);
  a65=(a43*a50);
  a65=(a54?a65:0);
  a60=(a60-a65);
  if (res[0]!=0) res[0][62]=a60;
  a62=(a62*a61);
  a57=(a57*a50);
  a57=(a54?a57:0);
  a62=(a62-a57);
  if (res[0]!=0) res[0][63]=a62;
  a47=(a47*a61);
  a63=(a63*a50);
  a63=(a54?a63:0);
  a47=(a47-a63);
  if (res[0]!=0) res[0][64]=a47;
  a64=(a64*a50);
  a54=(a54?a64:0);
  a61=(a43*a61);
  a54=(a54+a61);
  a61=(-a54);
  if (res[0]!=0) res[0][65]=a61;
  if (res[0]!=0) res[0][66]=a42;
  if (res[0]!=0) res[0][67]=a43;
  if (res[0]!=0) res[0][68]=a44;
  a61=cos(a34);
  a64=cos(a35);
  a50=(a61*a64);
  a63=(a50*a55);
  a34=sin(a34);
  a57=(a64*a34);
  a65=sin(a33);
  a57=(a57*a65);
  a33=cos(a33);
  a35=sin(a35);
  a66=(a33*a35);
  a57=(a57-a66);
  a66=(a57*a46);
  a63=(a63+a66);
  a66=(a65*a35);
  a49=(a33*a64);
  a52=(a49*a34);
  a66=(a66+a52);
  a52=(a66*a53);
  a63=(a63+a52);
  if (res[0]!=0) res[0][69]=a63;
  a63=(a61*a35);
  a52=(a63*a55);
  a59=(a34*a65);
  a59=(a59*a35);
  a49=(a49+a59);
  a59=(a49*a46);
  a52=(a52+a59);
  a59=(a33*a34);
  a59=(a59*a35);
  a64=(a64*a65);
  a59=(a59-a64);
  a64=(a59*a53);
  a52=(a52+a64);
  if (res[0]!=0) res[0][70]=a52;
  a65=(a61*a65);
  a52=(a65*a46);
  a64=(a34*a55);
  a52=(a52-a64);
  a61=(a61*a33);
  a33=(a61*a53);
  a52=(a52+a33);
  if (res[0]!=0) res[0][71]=a52;
  a52=(a50*a56);
  a33=(a57*a48);
  a52=(a52+a33);
  a33=(a66*a51);
  a52=(a52-a33);
  if (res[0]!=0) res[0][72]=a52;
  a52=(a63*a56);
  a33=(a49*a48);
  a52=(a52+a33);
  a33=(a59*a51);
  a52=(a52-a33);
  if (res[0]!=0) res[0][73]=a52;
  a52=(a65*a48);
  a33=(a34*a56);
  a52=(a52-a33);
  a33=(a61*a51);
  a52=(a52-a33);
  if (res[0]!=0) res[0][74]=a52;
  a50=(a50*a39);
  a57=(a57*a40);
  a50=(a50+a57);
  a66=(a66*a41);
  a50=(a50+a66);
  if (res[0]!=0) res[0][75]=a50;
  a63=(a63*a39);
  a49=(a49*a40);
  a63=(a63+a49);
  a59=(a59*a41);
  a63=(a63+a59);
  if (res[0]!=0) res[0][76]=a63;
  a65=(a65*a40);
  a34=(a34*a39);
  a65=(a65-a34);
  a61=(a61*a41);
  a65=(a65+a61);
  if (res[0]!=0) res[0][77]=a65;
  a65=cos(a37);
  a61=cos(a38);
  a34=(a65*a61);
  a63=(a34*a55);
  a38=sin(a38);
  a59=(a65*a38);
  a49=(a59*a46);
  a63=(a63+a49);
  a37=sin(a37);
  a49=(a37*a53);
  a63=(a63-a49);
  a49=(a58*a63);
  a50=(a61*a37);
  a66=sin(a36);
  a50=(a50*a66);
  a36=cos(a36);
  a57=(a36*a38);
  a50=(a50-a57);
  a57=(a50*a55);
  a52=(a36*a61);
  a33=(a37*a66);
  a33=(a33*a38);
  a33=(a52+a33);
  a64=(a33*a46);
  a57=(a57+a64);
  a64=(a65*a66);
  a35=(a64*a53);
  a57=(a57+a35);
  a35=(a45*a57);
  a49=(a49+a35);
  a35=(a66*a38);
  a52=(a52*a37);
  a35=(a35+a52);
  a52=(a35*a55);
  a67=(a36*a37);
  a67=(a67*a38);
  a61=(a61*a66);
  a67=(a67-a61);
  a61=(a67*a46);
  a52=(a52+a61);
  a65=(a65*a36);
  a36=(a65*a53);
  a52=(a52+a36);
  a36=(a60*a52);
  a49=(a49+a36);
  if (res[0]!=0) res[0][78]=a49;
  a49=(a34*a56);
  a36=(a59*a48);
  a49=(a49+a36);
  a36=(a37*a51);
  a49=(a49+a36);
  a36=(a58*a49);
  a61=(a50*a56);
  a66=(a33*a48);
  a61=(a61+a66);
  a66=(a64*a51);
  a61=(a61-a66);
  a66=(a45*a61);
  a36=(a36+a66);
  a66=(a35*a56);
  a38=(a67*a48);
  a66=(a66+a38);
  a38=(a65*a51);
  a66=(a66-a38);
  a38=(a60*a66);
  a36=(a36+a38);
  if (res[0]!=0) res[0][79]=a36;
  a34=(a34*a39);
  a59=(a59*a40);
  a34=(a34+a59);
  a37=(a37*a41);
  a34=(a34-a37);
  a37=(a58*a34);
  a50=(a50*a39);
  a33=(a33*a40);
  a50=(a50+a33);
  a64=(a64*a41);
  a50=(a50+a64);
  a64=(a45*a50);
  a37=(a37+a64);
  a35=(a35*a39);
  a67=(a67*a40);
  a35=(a35+a67);
  a65=(a65*a41);
  a35=(a35+a65);
  a65=(a60*a35);
  a37=(a37+a65);
  if (res[0]!=0) res[0][80]=a37;
  a37=(a62*a63);
  a65=(a47*a57);
  a37=(a37+a65);
  a65=(a54*a52);
  a37=(a37-a65);
  if (res[0]!=0) res[0][81]=a37;
  a37=(a62*a49);
  a65=(a47*a61);
  a37=(a37+a65);
  a65=(a54*a66);
  a37=(a37-a65);
  if (res[0]!=0) res[0][82]=a37;
  a37=(a62*a34);
  a65=(a47*a50);
  a37=(a37+a65);
  a65=(a54*a35);
  a37=(a37-a65);
  if (res[0]!=0) res[0][83]=a37;
  a63=(a42*a63);
  a57=(a43*a57);
  a63=(a63+a57);
  a52=(a44*a52);
  a63=(a63+a52);
  if (res[0]!=0) res[0][84]=a63;
  a49=(a42*a49);
  a61=(a43*a61);
  a49=(a49+a61);
  a66=(a44*a66);
  a49=(a49+a66);
  if (res[0]!=0) res[0][85]=a49;
  a34=(a42*a34);
  a50=(a43*a50);
  a34=(a34+a50);
  a35=(a44*a35);
  a34=(a34+a35);
  if (res[0]!=0) res[0][86]=a34;
  if (res[0]!=0) res[0][87]=a27;
  if (res[0]!=0) res[0][88]=a28;
  if (res[0]!=0) res[0][89]=a29;
  a29=(a55*a30);
  a28=(a46*a31);
  a29=(a29+a28);
  a28=(a53*a32);
  a29=(a29+a28);
  if (res[0]!=0) res[0][90]=a29;
  a29=(a56*a30);
  a28=(a48*a31);
  a29=(a29+a28);
  a28=(a51*a32);
  a29=(a29-a28);
  if (res[0]!=0) res[0][91]=a29;
  a30=(a39*a30);
  a31=(a40*a31);
  a30=(a30+a31);
  a32=(a41*a32);
  a30=(a30+a32);
  if (res[0]!=0) res[0][92]=a30;
  if (res[0]!=0) res[0][93]=a00;
  if (res[0]!=0) res[0][94]=a01;
  if (res[0]!=0) res[0][95]=a02;
  a02=(a55*a03);
  a01=(a46*a04);
  a02=(a02+a01);
  a01=(a53*a05);
  a02=(a02+a01);
  if (res[0]!=0) res[0][96]=a02;
  a02=(a56*a03);
  a01=(a48*a04);
  a02=(a02+a01);
  a01=(a51*a05);
  a02=(a02-a01);
  if (res[0]!=0) res[0][97]=a02;
  a03=(a39*a03);
  a04=(a40*a04);
  a03=(a03+a04);
  a05=(a41*a05);
  a03=(a03+a05);
  if (res[0]!=0) res[0][98]=a03;
  a03=(a58*a06);
  a05=(a45*a07);
  a03=(a03+a05);
  a05=(a60*a08);
  a03=(a03+a05);
  if (res[0]!=0) res[0][99]=a03;
  a03=(a62*a06);
  a05=(a47*a07);
  a03=(a03+a05);
  a05=(a54*a08);
  a03=(a03-a05);
  if (res[0]!=0) res[0][100]=a03;
  a06=(a42*a06);
  a07=(a43*a07);
  a06=(a06+a07);
  a08=(a44*a08);
  a06=(a06+a08);
  if (res[0]!=0) res[0][101]=a06;
  if (res[0]!=0) res[0][102]=a09;
  if (res[0]!=0) res[0][103]=a10;
  if (res[0]!=0) res[0][104]=a11;
  if (res[0]!=0) res[0][105]=a12;
  if (res[0]!=0) res[0][106]=a13;
  if (res[0]!=0) res[0][107]=a14;
  a14=(a15*a55);
  a13=(a18*a46);
  a14=(a14+a13);
  a13=(a19*a53);
  a14=(a14+a13);
  a13=(a55*a14);
  a12=(a18*a55);
  a11=(a16*a46);
  a12=(a12+a11);
  a11=(a20*a53);
  a12=(a12+a11);
  a11=(a46*a12);
  a13=(a13+a11);
  a55=(a19*a55);
  a46=(a20*a46);
  a55=(a55+a46);
  a46=(a17*a53);
  a55=(a55+a46);
  a53=(a53*a55);
  a13=(a13+a53);
  if (res[0]!=0) res[0][108]=a13;
  a13=(a15*a56);
  a53=(a18*a48);
  a13=(a13+a53);
  a53=(a19*a51);
  a13=(a13-a53);
  a53=(a56*a13);
  a46=(a18*a56);
  a11=(a16*a48);
  a46=(a46+a11);
  a11=(a20*a51);
  a46=(a46-a11);
  a11=(a48*a46);
  a53=(a53+a11);
  a11=(a19*a56);
  a10=(a20*a48);
  a11=(a11+a10);
  a10=(a17*a51);
  a11=(a11-a10);
  a10=(a51*a11);
  a53=(a53-a10);
  if (res[0]!=0) res[0][109]=a53;
  a15=(a15*a39);
  a53=(a18*a40);
  a15=(a15+a53);
  a53=(a19*a41);
  a15=(a15+a53);
  a15=(a39*a15);
  a18=(a18*a39);
  a16=(a16*a40);
  a18=(a18+a16);
  a16=(a20*a41);
  a18=(a18+a16);
  a18=(a40*a18);
  a15=(a15+a18);
  a19=(a19*a39);
  a20=(a20*a40);
  a19=(a19+a20);
  a17=(a17*a41);
  a19=(a19+a17);
  a19=(a41*a19);
  a15=(a15+a19);
  if (res[0]!=0) res[0][110]=a15;
  a56=(a56*a14);
  a48=(a48*a12);
  a56=(a56+a48);
  a51=(a51*a55);
  a56=(a56-a51);
  if (res[0]!=0) res[0][111]=a56;
  a14=(a39*a14);
  a12=(a40*a12);
  a14=(a14+a12);
  a55=(a41*a55);
  a14=(a14+a55);
  if (res[0]!=0) res[0][112]=a14;
  a39=(a39*a13);
  a40=(a40*a46);
  a39=(a39+a40);
  a41=(a41*a11);
  a39=(a39+a41);
  if (res[0]!=0) res[0][113]=a39;
  a39=(a21*a58);
  a41=(a24*a45);
  a39=(a39+a41);
  a41=(a25*a60);
  a39=(a39+a41);
  a41=(a58*a39);
  a11=(a24*a58);
  a40=(a22*a45);
  a11=(a11+a40);
  a40=(a26*a60);
  a11=(a11+a40);
  a40=(a45*a11);
  a41=(a41+a40);
  a58=(a25*a58);
  a45=(a26*a45);
  a58=(a58+a45);
  a45=(a23*a60);
  a58=(a58+a45);
  a60=(a60*a58);
  a41=(a41+a60);
  if (res[0]!=0) res[0][114]=a41;
  a41=(a21*a62);
  a60=(a24*a47);
  a41=(a41+a60);
  a60=(a25*a54);
  a41=(a41-a60);
  a60=(a62*a41);
  a45=(a24*a62);
  a40=(a22*a47);
  a45=(a45+a40);
  a40=(a26*a54);
  a45=(a45-a40);
  a40=(a47*a45);
  a60=(a60+a40);
  a40=(a25*a62);
  a46=(a26*a47);
  a40=(a40+a46);
  a46=(a23*a54);
  a40=(a40-a46);
  a46=(a54*a40);
  a60=(a60-a46);
  if (res[0]!=0) res[0][115]=a60;
  a21=(a21*a42);
  a60=(a24*a43);
  a21=(a21+a60);
  a60=(a25*a44);
  a21=(a21+a60);
  a21=(a42*a21);
  a24=(a24*a42);
  a22=(a22*a43);
  a24=(a24+a22);
  a22=(a26*a44);
  a24=(a24+a22);
  a24=(a43*a24);
  a21=(a21+a24);
  a25=(a25*a42);
  a26=(a26*a43);
  a25=(a25+a26);
  a23=(a23*a44);
  a25=(a25+a23);
  a25=(a44*a25);
  a21=(a21+a25);
  if (res[0]!=0) res[0][116]=a21;
  a62=(a62*a39);
  a47=(a47*a11);
  a62=(a62+a47);
  a54=(a54*a58);
  a62=(a62-a54);
  if (res[0]!=0) res[0][117]=a62;
  a39=(a42*a39);
  a11=(a43*a11);
  a39=(a39+a11);
  a58=(a44*a58);
  a39=(a39+a58);
  if (res[0]!=0) res[0][118]=a39;
  a42=(a42*a41);
  a43=(a43*a45);
  a42=(a42+a43);
  a44=(a44*a40);
  a42=(a42+a44);
  if (res[0]!=0) res[0][119]=a42;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_derived_parameters(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_derived_parameters_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_derived_parameters_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_derived_parameters_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_derived_parameters_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_derived_parameters_n_in(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_derived_parameters_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_derived_parameters_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_derived_parameters_name_in(casadi_int i) {
  switch (i) {
    case 0: return "link_mass";
    case 1: return "link_com";
    case 2: return "link_inertia";
    case 3: return "joint_xyz";
    case 4: return "joint_rpy";
    case 5: return "joint_axis";
    case 6: return "gravity";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_derived_parameters_name_out(casadi_int i) {
  switch (i) {
    case 0: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_derived_parameters_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    case 6: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_derived_parameters_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_derived_parameters_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_derived_parameters_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7*sizeof(const casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_derived_parameters(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[7];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 69);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 7; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    r[0] = res[0] + i * 120;
    if (snakecg_sp2_derived_parameters(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
