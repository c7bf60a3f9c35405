/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for derived_parameters() of
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
  casadi_real a60, a61, a62, a63, a64, a65;
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
  if (res[0]!=0) res[0][51]=a52;
  a40=(a40*a46);
  a46=(a39*a40);
  a50=(a46/a51);
  a50=(-a50);
  a50=(a48?a50:0);
  a46=(a46/a54);
  a55=(-a46);
  a55=(a53?a55:0);
  a55=(a50+a55);
  if (res[0]!=0) res[0][52]=a55;
  a56=(-a39);
  a56=(a48?a56:0);
  a57=(a53?a39:0);
  a56=(a56+a57);
  if (res[0]!=0) res[0][53]=a56;
  a46=(a53?a46:0);
  a50=(a50+a46);
  if (res[0]!=0) res[0][54]=a50;
  a46=casadi_sq(a40);
  a51=(a46/a51);
  a51=(a49-a51);
  a48=(a48?a51:0);
  a46=(a46/a54);
  a46=(a46-a49);
  a53=(a53?a46:0);
  a48=(a48+a53);
  if (res[0]!=0) res[0][55]=a48;
  a53=(-a40);
  if (res[0]!=0) res[0][56]=a53;
  if (res[0]!=0) res[0][57]=a39;
  if (res[0]!=0) res[0][58]=a40;
  if (res[0]!=0) res[0][59]=a41;
  a53=casadi_sq(a42);
  a46=casadi_sq(a43);
  a53=(a53+a46);
  a46=casadi_sq(a44);
  a53=(a53+a46);
  a53=pow(a53,a47);
  a44=(a44*a53);
  a45=(a45<=a44);
  a42=(a42*a53);
  a47=casadi_sq(a42);
  a46=(a49+a44);
  a54=(a47/a46);
  a54=(a49-a54);
  a54=(a45?a54:0);
  a51=(!a45);
  a57=(a49-a44);
  a47=(a47/a57);
  a47=(a49-a47);
  a47=(a51?a47:0);
  a54=(a54+a47);
  if (res[0]!=0) res[0][60]=a54;
  a43=(a43*a53);
  a53=(a42*a43);
  a47=(a53/a46);
  a47=(-a47);
  a47=(a45?a47:0);
  a53=(a53/a57);
  a58=(-a53);
  a58=(a51?a58:0);
  a58=(a47+a58);
  if (res[0]!=0) res[0][61]=a58;
  a59=(-a42);
  a59=(a45?a59:0);
  a60=(a51?a42:0);
  a59=(a59+a60);
  if (res[0]!=0) res[0][62]=a59;
  a53=(a51?a53:0);
  a47=(a47+a53);
  if (res[0]!=0) res[0][63]=a47;
  a53=casadi_sq(a43);
  a46=(a53/a46);
  a46=(a49-a46);
  a45=(a45?a46:0);
  a53=(a53/a57);
  a53=(a53-a49);
  a51=(a51?a53:0);
  a45=(a45+a51);
  if (res[0]!=0) res[0][64]=a45;
  a51=(-a43);
  if (res[0]!=0) res[0][65]=a51;
  if (res[0]!=0) res[0][66]=a42;
  if (res[0]!=0) res[0][67]=a43;
  if (res[0]!=0) res[0][68]=a44;
  a51=cos(a34);
  a53=cos(a35);
  a49=(a51*a53);
  a57=(a49*a52);
  a34=sin(a34);
  a46=(a53*a34);
  a60=sin(a33);
  a46=(a46*a60);
  a33=cos(a33);
  a35=sin(a35);
  a61=(a33*a35);
  a46=(a46-a61);
  a61=(a46*a55);
  a57=(a57+a61);
  a61=(a60*a35);
  a62=(a33*a53);
  a63=(a62*a34);
  a61=(a61+a63);
  a63=(a61*a56);
  a57=(a57+a63);
  if (res[0]!=0) res[0][69]=a57;
  a57=(a51*a35);
  a63=(a57*a52);
  a64=(a34*a60);
  a64=(a64*a35);
  a62=(a62+a64);
  a64=(a62*a55);
  a63=(a63+a64);
  a64=(a33*a34);
  a64=(a64*a35);
  a53=(a53*a60);
  a64=(a64-a53);
  a53=(a64*a56);
  a63=(a63+a53);
  if (res[0]!=0) res[0][70]=a63;
  a60=(a51*a60);
  a63=(a60*a55);
  a53=(a34*a52);
  a63=(a63-a53);
  a51=(a51*a33);
  a33=(a51*a56);
  a63=(a63+a33);
  if (res[0]!=0) res[0][71]=a63;
  a63=(a49*a50);
  a33=(a46*a48);
  a63=(a63+a33);
  a33=(a61*a40);
  a63=(a63-a33);
  if (res[0]!=0) res[0][72]=a63;
  a63=(a57*a50);
  a33=(a62*a48);
  a63=(a63+a33);
  a33=(a64*a40);
  a63=(a63-a33);
  if (res[0]!=0) res[0][73]=a63;
  a63=(a60*a48);
  a33=(a34*a50);
  a63=(a63-a33);
  a33=(a51*a40);
  a63=(a63-a33);
  if (res[0]!=0) res[0][74]=a63;
  a49=(a49*a39);
  a46=(a46*a40);
  a49=(a49+a46);
  a61=(a61*a41);
  a49=(a49+a61);
  if (res[0]!=0) res[0][75]=a49;
  a57=(a57*a39);
  a62=(a62*a40);
  a57=(a57+a62);
  a64=(a64*a41);
  a57=(a57+a64);
  if (res[0]!=0) res[0][76]=a57;
  a60=(a60*a40);
  a34=(a34*a39);
  a60=(a60-a34);
  a51=(a51*a41);
  a60=(a60+a51);
  if (res[0]!=0) res[0][77]=a60;
  a60=cos(a37);
  a51=cos(a38);
  a34=(a60*a51);
  a57=(a34*a52);
  a38=sin(a38);
  a64=(a60*a38);
  a62=(a64*a55);
  a57=(a57+a62);
  a37=sin(a37);
  a62=(a37*a56);
  a57=(a57-a62);
  a62=(a54*a57);
  a49=(a51*a37);
  a61=sin(a36);
  a49=(a49*a61);
  a36=cos(a36);
  a46=(a36*a38);
  a49=(a49-a46);
  a46=(a49*a52);
  a63=(a36*a51);
  a33=(a37*a61);
  a33=(a33*a38);
  a33=(a63+a33);
  a53=(a33*a55);
  a46=(a46+a53);
  a53=(a60*a61);
  a35=(a53*a56);
  a46=(a46+a35);
  a35=(a58*a46);
  a62=(a62+a35);
  a35=(a61*a38);
  a63=(a63*a37);
  a35=(a35+a63);
  a63=(a35*a52);
  a65=(a36*a37);
  a65=(a65*a38);
  a51=(a51*a61);
  a65=(a65-a51);
  a51=(a65*a55);
  a63=(a63+a51);
  a60=(a60*a36);
  a36=(a60*a56);
  a63=(a63+a36);
  a36=(a59*a63);
  a62=(a62+a36);
  if (res[0]!=0) res[0][78]=a62;
  a62=(a34*a50);
  a36=(a64*a48);
  a62=(a62+a36);
  a36=(a37*a40);
  a62=(a62+a36);
  a36=(a54*a62);
  a51=(a49*a50);
  a61=(a33*a48);
  a51=(a51+a61);
  a61=(a53*a40);
  a51=(a51-a61);
  a61=(a58*a51);
  a36=(a36+a61);
  a61=(a35*a50);
  a38=(a65*a48);
  a61=(a61+a38);
  a38=(a60*a40);
  a61=(a61-a38);
  a38=(a59*a61);
  a36=(a36+a38);
  if (res[0]!=0) res[0][79]=a36;
  a34=(a34*a39);
  a64=(a64*a40);
  a34=(a34+a64);
  a37=(a37*a41);
  a34=(a34-a37);
  a37=(a54*a34);
  a49=(a49*a39);
  a33=(a33*a40);
  a49=(a49+a33);
  a53=(a53*a41);
  a49=(a49+a53);
  a53=(a58*a49);
  a37=(a37+a53);
  a35=(a35*a39);
  a65=(a65*a40);
  a35=(a35+a65);
  a60=(a60*a41);
  a35=(a35+a60);
  a60=(a59*a35);
  a37=(a37+a60);
  if (res[0]!=0) res[0][80]=a37;
  a37=(a47*a57);
  a60=(a45*a46);
  a37=(a37+a60);
  a60=(a43*a63);
  a37=(a37-a60);
  if (res[0]!=0) res[0][81]=a37;
  a37=(a47*a62);
  a60=(a45*a51);
  a37=(a37+a60);
  a60=(a43*a61);
  a37=(a37-a60);
  if (res[0]!=0) res[0][82]=a37;
  a37=(a47*a34);
  a60=(a45*a49);
  a37=(a37+a60);
  a60=(a43*a35);
  a37=(a37-a60);
  if (res[0]!=0) res[0][83]=a37;
  a57=(a42*a57);
  a46=(a43*a46);
  a57=(a57+a46);
  a63=(a44*a63);
  a57=(a57+a63);
  if (res[0]!=0) res[0][84]=a57;
  a62=(a42*a62);
  a51=(a43*a51);
  a62=(a62+a51);
  a61=(a44*a61);
  a62=(a62+a61);
  if (res[0]!=0) res[0][85]=a62;
  a34=(a42*a34);
  a49=(a43*a49);
  a34=(a34+a49);
  a35=(a44*a35);
  a34=(a34+a35);
  if (res[0]!=0) res[0][86]=a34;
  if (res[0]!=0) res[0][87]=a27;
  if (res[0]!=0) res[0][88]=a28;
  if (res[0]!=0) res[0][89]=a29;
  a29=(a52*a30);
  a28=(a55*a31);
  a29=(a29+a28);
  a28=(a56*a32);
  a29=(a29+a28);
  if (res[0]!=0) res[0][90]=a29;
  a29=(a50*a30);
  a28=(a48*a31);
  a29=(a29+a28);
  a28=(a40*a32);
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
  a02=(a52*a03);
  a01=(a55*a04);
  a02=(a02+a01);
  a01=(a56*a05);
  a02=(a02+a01);
  if (res[0]!=0) res[0][96]=a02;
  a02=(a50*a03);
  a01=(a48*a04);
  a02=(a02+a01);
  a01=(a40*a05);
  a02=(a02-a01);
  if (res[0]!=0) res[0][97]=a02;
  a03=(a39*a03);
  a04=(a40*a04);
  a03=(a03+a04);
  a05=(a41*a05);
  a03=(a03+a05);
  if (res[0]!=0) res[0][98]=a03;
  a03=(a54*a06);
  a05=(a58*a07);
  a03=(a03+a05);
  a05=(a59*a08);
  a03=(a03+a05);
  if (res[0]!=0) res[0][99]=a03;
  a03=(a47*a06);
  a05=(a45*a07);
  a03=(a03+a05);
  a05=(a43*a08);
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
  a14=(a15*a52);
  a13=(a18*a55);
  a14=(a14+a13);
  a13=(a19*a56);
  a14=(a14+a13);
  a13=(a52*a14);
  a12=(a18*a52);
  a11=(a16*a55);
  a12=(a12+a11);
  a11=(a20*a56);
  a12=(a12+a11);
  a11=(a55*a12);
  a13=(a13+a11);
  a52=(a19*a52);
  a55=(a20*a55);
  a52=(a52+a55);
  a55=(a17*a56);
  a52=(a52+a55);
  a56=(a56*a52);
  a13=(a13+a56);
  if (res[0]!=0) res[0][108]=a13;
  a13=(a15*a50);
  a56=(a18*a48);
  a13=(a13+a56);
  a56=(a19*a40);
  a13=(a13-a56);
  a56=(a50*a13);
  a55=(a18*a50);
  a11=(a16*a48);
  a55=(a55+a11);
  a11=(a20*a40);
  a55=(a55-a11);
  a10=(a48*a55);
  a56=(a56+a10);
  a10=(a19*a50);
  a09=(a20*a48);
  a10=(a10+a09);
  a09=(a17*a40);
  a10=(a10-a09);
  a09=(a40*a10);
  a56=(a56-a09);
  if (res[0]!=0) res[0][109]=a56;
  a15=(a15*a39);
  a56=(a18*a40);
  a15=(a15+a56);
  a56=(a19*a41);
  a15=(a15+a56);
  a15=(a39*a15);
  a18=(a18*a39);
  a16=(a16*a40);
  a18=(a18+a16);
  a20=(a20*a41);
  a18=(a18+a20);
  a18=(a40*a18);
  a15=(a15+a18);
  a19=(a19*a39);
  a19=(a19+a11);
  a17=(a17*a41);
  a19=(a19+a17);
  a19=(a41*a19);
  a15=(a15+a19);
  if (res[0]!=0) res[0][110]=a15;
  a50=(a50*a14);
  a48=(a48*a12);
  a50=(a50+a48);
  a48=(a40*a52);
  a50=(a50-a48);
  if (res[0]!=0) res[0][111]=a50;
  a14=(a39*a14);
  a12=(a40*a12);
  a14=(a14+a12);
  a52=(a41*a52);
  a14=(a14+a52);
  if (res[0]!=0) res[0][112]=a14;
  a39=(a39*a13);
  a40=(a40*a55);
  a39=(a39+a40);
  a41=(a41*a10);
  a39=(a39+a41);
  if (res[0]!=0) res[0][113]=a39;
  a39=(a21*a54);
  a41=(a24*a58);
  a39=(a39+a41);
  a41=(a25*a59);
  a39=(a39+a41);
  a41=(a54*a39);
  a10=(a24*a54);
  a40=(a22*a58);
  a10=(a10+a40);
  a40=(a26*a59);
  a10=(a10+a40);
  a40=(a58*a10);
  a41=(a41+a40);
  a54=(a25*a54);
  a58=(a26*a58);
  a54=(a54+a58);
  a58=(a23*a59);
  a54=(a54+a58);
  a59=(a59*a54);
  a41=(a41+a59);
  if (res[0]!=0) res[0][114]=a41;
  a41=(a21*a47);
  a59=(a24*a45);
  a41=(a41+a59);
  a59=(a25*a43);
  a41=(a41-a59);
  a59=(a47*a41);
  a58=(a24*a47);
  a40=(a22*a45);
  a58=(a58+a40);
  a40=(a26*a43);
  a58=(a58-a40);
  a55=(a45*a58);
  a59=(a59+a55);
  a55=(a25*a47);
  a13=(a26*a45);
  a55=(a55+a13);
  a13=(a23*a43);
  a55=(a55-a13);
  a13=(a43*a55);
  a59=(a59-a13);
  if (res[0]!=0) res[0][115]=a59;
  a21=(a21*a42);
  a59=(a24*a43);
  a21=(a21+a59);
  a59=(a25*a44);
  a21=(a21+a59);
  a21=(a42*a21);
  a24=(a24*a42);
  a22=(a22*a43);
  a24=(a24+a22);
  a26=(a26*a44);
  a24=(a24+a26);
  a24=(a43*a24);
  a21=(a21+a24);
  a25=(a25*a42);
  a25=(a25+a40);
  a23=(a23*a44);
  a25=(a25+a23);
  a25=(a44*a25);
  a21=(a21+a25);
  if (res[0]!=0) res[0][116]=a21;
  a47=(a47*a39);
  a45=(a45*a10);
  a47=(a47+a45);
  a45=(a43*a54);
  a47=(a47-a45);
  if (res[0]!=0) res[0][117]=a47;
  a39=(a42*a39);
  a10=(a43*a10);
  a39=(a39+a10);
  a54=(a44*a54);
  a39=(a39+a54);
  if (res[0]!=0) res[0][118]=a39;
  a42=(a42*a41);
  a43=(a43*a58);
  a42=(a42+a43);
  a44=(a44*a55);
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
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 67);
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
