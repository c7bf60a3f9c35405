/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for link_jacobians() of
 * generated/spatial/na3/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: 82d64716a2089350522ee6ce607152c94df1120870c00e7b42763fcf4d7df073
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp3_link_jacobians_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp3_link_jacobians_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp3_link_jacobians_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp3_link_jacobians_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {10, 1, 1};
static const casadi_int casadi_s1[3] = {169, 1, 1};
static const casadi_int casadi_s2[3] = {24, 9, 1};

/* snakecg_sp3_link_jacobians:(q[10],K[169])->(J[24x9]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58;
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
  if (res[0]!=0) res[0][0]=a04;
  a07=arg[0]? arg[0][6] : 0;
  a08=(2.*a07);
  a09=(a08*a05);
  a10=arg[0]? arg[0][3] : 0;
  a11=(2.*a10);
  a12=(a11*a02);
  a09=(a09+a12);
  if (res[0]!=0) res[0][1]=a09;
  a07=(a01*a07);
  a13=(a07*a02);
  a11=(a11*a05);
  a13=(a13+a11);
  if (res[0]!=0) res[0][2]=a13;
  a14=0.;
  if (res[0]!=0) res[0][3]=a14;
  if (res[0]!=0) res[0][4]=a14;
  if (res[0]!=0) res[0][5]=a14;
  if (res[0]!=0) res[0][6]=a04;
  if (res[0]!=0) res[0][7]=a09;
  if (res[0]!=0) res[0][8]=a13;
  if (res[0]!=0) res[0][9]=a14;
  if (res[0]!=0) res[0][10]=a14;
  if (res[0]!=0) res[0][11]=a14;
  if (res[0]!=0) res[0][12]=a04;
  if (res[0]!=0) res[0][13]=a09;
  if (res[0]!=0) res[0][14]=a13;
  if (res[0]!=0) res[0][15]=a14;
  if (res[0]!=0) res[0][16]=a14;
  if (res[0]!=0) res[0][17]=a14;
  if (res[0]!=0) res[0][18]=a04;
  if (res[0]!=0) res[0][19]=a09;
  if (res[0]!=0) res[0][20]=a13;
  if (res[0]!=0) res[0][21]=a14;
  if (res[0]!=0) res[0][22]=a14;
  if (res[0]!=0) res[0][23]=a14;
  a15=(a07*a05);
  a15=(a15+a12);
  if (res[0]!=0) res[0][24]=a15;
  a12=casadi_sq(a10);
  a01=(a01*a12);
  a00=(a00+a01);
  a06=(a00+a06);
  if (res[0]!=0) res[0][25]=a06;
  a01=(a08*a10);
  a12=(2.*a02);
  a12=(a12*a05);
  a01=(a01+a12);
  if (res[0]!=0) res[0][26]=a01;
  if (res[0]!=0) res[0][27]=a14;
  if (res[0]!=0) res[0][28]=a14;
  if (res[0]!=0) res[0][29]=a14;
  if (res[0]!=0) res[0][30]=a15;
  if (res[0]!=0) res[0][31]=a06;
  if (res[0]!=0) res[0][32]=a01;
  if (res[0]!=0) res[0][33]=a14;
  if (res[0]!=0) res[0][34]=a14;
  if (res[0]!=0) res[0][35]=a14;
  if (res[0]!=0) res[0][36]=a15;
  if (res[0]!=0) res[0][37]=a06;
  if (res[0]!=0) res[0][38]=a01;
  if (res[0]!=0) res[0][39]=a14;
  if (res[0]!=0) res[0][40]=a14;
  if (res[0]!=0) res[0][41]=a14;
  if (res[0]!=0) res[0][42]=a15;
  if (res[0]!=0) res[0][43]=a06;
  if (res[0]!=0) res[0][44]=a01;
  if (res[0]!=0) res[0][45]=a14;
  if (res[0]!=0) res[0][46]=a14;
  if (res[0]!=0) res[0][47]=a14;
  a08=(a08*a02);
  a08=(a08+a11);
  if (res[0]!=0) res[0][48]=a08;
  a07=(a07*a10);
  a07=(a07+a12);
  if (res[0]!=0) res[0][49]=a07;
  a00=(a00+a03);
  if (res[0]!=0) res[0][50]=a00;
  if (res[0]!=0) res[0][51]=a14;
  if (res[0]!=0) res[0][52]=a14;
  if (res[0]!=0) res[0][53]=a14;
  if (res[0]!=0) res[0][54]=a08;
  if (res[0]!=0) res[0][55]=a07;
  if (res[0]!=0) res[0][56]=a00;
  if (res[0]!=0) res[0][57]=a14;
  if (res[0]!=0) res[0][58]=a14;
  if (res[0]!=0) res[0][59]=a14;
  if (res[0]!=0) res[0][60]=a08;
  if (res[0]!=0) res[0][61]=a07;
  if (res[0]!=0) res[0][62]=a00;
  if (res[0]!=0) res[0][63]=a14;
  if (res[0]!=0) res[0][64]=a14;
  if (res[0]!=0) res[0][65]=a14;
  if (res[0]!=0) res[0][66]=a08;
  if (res[0]!=0) res[0][67]=a07;
  if (res[0]!=0) res[0][68]=a00;
  if (res[0]!=0) res[0][69]=a14;
  if (res[0]!=0) res[0][70]=a14;
  if (res[0]!=0) res[0][71]=a14;
  if (res[0]!=0) res[0][72]=a14;
  if (res[0]!=0) res[0][73]=a14;
  if (res[0]!=0) res[0][74]=a14;
  if (res[0]!=0) res[0][75]=a04;
  if (res[0]!=0) res[0][76]=a09;
  if (res[0]!=0) res[0][77]=a13;
  a03=arg[1]? arg[1][124] : 0;
  a12=(a13*a03);
  a10=arg[1]? arg[1][125] : 0;
  a11=(a01*a10);
  a12=(a12+a11);
  a11=arg[1]? arg[1][126] : 0;
  a02=(a00*a11);
  a12=(a12+a02);
  a02=(a09*a12);
  a05=(a09*a03);
  a16=(a06*a10);
  a05=(a05+a16);
  a16=(a07*a11);
  a05=(a05+a16);
  a16=(a13*a05);
  a02=(a02-a16);
  if (res[0]!=0) res[0][78]=a02;
  a03=(a04*a03);
  a10=(a15*a10);
  a03=(a03+a10);
  a11=(a08*a11);
  a03=(a03+a11);
  a11=(a13*a03);
  a10=(a04*a12);
  a11=(a11-a10);
  if (res[0]!=0) res[0][79]=a11;
  a11=(a04*a05);
  a10=(a09*a03);
  a11=(a11-a10);
  if (res[0]!=0) res[0][80]=a11;
  if (res[0]!=0) res[0][81]=a04;
  if (res[0]!=0) res[0][82]=a09;
  if (res[0]!=0) res[0][83]=a13;
  a11=arg[1]? arg[1][103] : 0;
  a10=(a11*a13);
  a02=arg[1]? arg[1][104] : 0;
  a16=(a02*a01);
  a10=(a10+a16);
  a16=arg[1]? arg[1][105] : 0;
  a17=(a16*a00);
  a10=(a10+a17);
  a17=arg[1]? arg[1][129] : 0;
  a18=(a10*a17);
  a19=arg[1]? arg[1][97] : 0;
  a20=(a19*a13);
  a21=arg[1]? arg[1][98] : 0;
  a22=(a21*a01);
  a20=(a20+a22);
  a22=arg[1]? arg[1][99] : 0;
  a23=(a22*a00);
  a20=(a20+a23);
  a23=arg[0]? arg[0][7] : 0;
  a24=cos(a23);
  a25=(a20*a24);
  a26=arg[1]? arg[1][100] : 0;
  a27=(a26*a13);
  a28=arg[1]? arg[1][101] : 0;
  a29=(a28*a01);
  a27=(a27+a29);
  a29=arg[1]? arg[1][102] : 0;
  a30=(a29*a00);
  a27=(a27+a30);
  a23=sin(a23);
  a30=(a27*a23);
  a25=(a25+a30);
  a30=arg[1]? arg[1][127] : 0;
  a31=(a25*a30);
  a18=(a18+a31);
  a27=(a27*a24);
  a20=(a20*a23);
  a27=(a27-a20);
  a20=arg[1]? arg[1][128] : 0;
  a31=(a27*a20);
  a18=(a18+a31);
  a31=arg[0]? arg[0][2] : 0;
  a32=(a12+a31);
  a33=(a18+a32);
  a34=(a33-a31);
  a35=(a09*a34);
  a36=(a11*a09);
  a37=(a02*a06);
  a36=(a36+a37);
  a37=(a16*a07);
  a36=(a36+a37);
  a37=(a36*a17);
  a38=(a19*a09);
  a39=(a21*a06);
  a38=(a38+a39);
  a39=(a22*a07);
  a38=(a38+a39);
  a39=(a38*a24);
  a40=(a26*a09);
  a41=(a28*a06);
  a40=(a40+a41);
  a41=(a29*a07);
  a40=(a40+a41);
  a41=(a40*a23);
  a39=(a39+a41);
  a41=(a39*a30);
  a37=(a37+a41);
  a40=(a40*a24);
  a38=(a38*a23);
  a40=(a40-a38);
  a38=(a40*a20);
  a37=(a37+a38);
  a38=arg[0]? arg[0][1] : 0;
  a41=(a05+a38);
  a42=(a37+a41);
  a43=(a42-a38);
  a44=(a13*a43);
  a35=(a35-a44);
  if (res[0]!=0) res[0][84]=a35;
  a11=(a11*a04);
  a02=(a02*a15);
  a11=(a11+a02);
  a16=(a16*a08);
  a11=(a11+a16);
  a17=(a11*a17);
  a19=(a19*a04);
  a21=(a21*a15);
  a19=(a19+a21);
  a22=(a22*a08);
  a19=(a19+a22);
  a22=(a19*a24);
  a26=(a26*a04);
  a28=(a28*a15);
  a26=(a26+a28);
  a29=(a29*a08);
  a26=(a26+a29);
  a29=(a26*a23);
  a22=(a22+a29);
  a30=(a22*a30);
  a17=(a17+a30);
  a26=(a26*a24);
  a19=(a19*a23);
  a26=(a26-a19);
  a20=(a26*a20);
  a17=(a17+a20);
  a20=arg[0]? arg[0][0] : 0;
  a19=(a03+a20);
  a23=(a17+a19);
  a24=(a23-a20);
  a30=(a13*a24);
  a29=(a04*a34);
  a30=(a30-a29);
  if (res[0]!=0) res[0][85]=a30;
  a30=(a04*a43);
  a29=(a09*a24);
  a30=(a30-a29);
  if (res[0]!=0) res[0][86]=a30;
  if (res[0]!=0) res[0][87]=a04;
  if (res[0]!=0) res[0][88]=a09;
  if (res[0]!=0) res[0][89]=a13;
  a30=arg[1]? arg[1][114] : 0;
  a29=(a10*a30);
  a28=arg[1]? arg[1][112] : 0;
  a21=(a28*a25);
  a29=(a29+a21);
  a21=arg[1]? arg[1][113] : 0;
  a16=(a21*a27);
  a29=(a29+a16);
  a16=arg[1]? arg[1][132] : 0;
  a02=(a29*a16);
  a35=arg[1]? arg[1][108] : 0;
  a44=(a10*a35);
  a45=arg[1]? arg[1][106] : 0;
  a46=(a45*a25);
  a44=(a44+a46);
  a46=arg[1]? arg[1][107] : 0;
  a47=(a46*a27);
  a44=(a44+a47);
  a47=arg[0]? arg[0][8] : 0;
  a48=cos(a47);
  a49=(a44*a48);
  a50=arg[1]? arg[1][111] : 0;
  a51=(a10*a50);
  a52=arg[1]? arg[1][109] : 0;
  a25=(a52*a25);
  a51=(a51+a25);
  a25=arg[1]? arg[1][110] : 0;
  a27=(a25*a27);
  a51=(a51+a27);
  a47=sin(a47);
  a27=(a51*a47);
  a49=(a49+a27);
  a27=arg[1]? arg[1][130] : 0;
  a53=(a49*a27);
  a02=(a02+a53);
  a51=(a51*a48);
  a44=(a44*a47);
  a51=(a51-a44);
  a44=arg[1]? arg[1][131] : 0;
  a53=(a51*a44);
  a02=(a02+a53);
  a33=(a02+a33);
  a31=(a33-a31);
  a53=(a09*a31);
  a54=(a36*a30);
  a55=(a28*a39);
  a54=(a54+a55);
  a55=(a21*a40);
  a54=(a54+a55);
  a55=(a54*a16);
  a56=(a36*a35);
  a57=(a45*a39);
  a56=(a56+a57);
  a57=(a46*a40);
  a56=(a56+a57);
  a57=(a56*a48);
  a58=(a36*a50);
  a39=(a52*a39);
  a58=(a58+a39);
  a40=(a25*a40);
  a58=(a58+a40);
  a40=(a58*a47);
  a57=(a57+a40);
  a40=(a57*a27);
  a55=(a55+a40);
  a58=(a58*a48);
  a56=(a56*a47);
  a58=(a58-a56);
  a56=(a58*a44);
  a55=(a55+a56);
  a42=(a55+a42);
  a38=(a42-a38);
  a56=(a13*a38);
  a53=(a53-a56);
  if (res[0]!=0) res[0][90]=a53;
  a30=(a11*a30);
  a28=(a28*a22);
  a30=(a30+a28);
  a21=(a21*a26);
  a30=(a30+a21);
  a16=(a30*a16);
  a35=(a11*a35);
  a45=(a45*a22);
  a35=(a35+a45);
  a46=(a46*a26);
  a35=(a35+a46);
  a46=(a35*a48);
  a50=(a11*a50);
  a52=(a52*a22);
  a50=(a50+a52);
  a25=(a25*a26);
  a50=(a50+a25);
  a25=(a50*a47);
  a46=(a46+a25);
  a27=(a46*a27);
  a16=(a16+a27);
  a50=(a50*a48);
  a35=(a35*a47);
  a50=(a50-a35);
  a44=(a50*a44);
  a16=(a16+a44);
  a23=(a16+a23);
  a20=(a23-a20);
  a44=(a13*a20);
  a35=(a04*a31);
  a44=(a44-a35);
  if (res[0]!=0) res[0][91]=a44;
  a44=(a04*a38);
  a35=(a09*a20);
  a44=(a44-a35);
  if (res[0]!=0) res[0][92]=a44;
  if (res[0]!=0) res[0][93]=a04;
  if (res[0]!=0) res[0][94]=a09;
  if (res[0]!=0) res[0][95]=a13;
  if (res[0]!=0) res[0][96]=a14;
  if (res[0]!=0) res[0][97]=a14;
  if (res[0]!=0) res[0][98]=a14;
  if (res[0]!=0) res[0][99]=a15;
  if (res[0]!=0) res[0][100]=a06;
  if (res[0]!=0) res[0][101]=a01;
  a13=(a06*a12);
  a09=(a01*a05);
  a13=(a13-a09);
  if (res[0]!=0) res[0][102]=a13;
  a13=(a01*a03);
  a09=(a15*a12);
  a13=(a13-a09);
  if (res[0]!=0) res[0][103]=a13;
  a13=(a15*a05);
  a09=(a06*a03);
  a13=(a13-a09);
  if (res[0]!=0) res[0][104]=a13;
  if (res[0]!=0) res[0][105]=a15;
  if (res[0]!=0) res[0][106]=a06;
  if (res[0]!=0) res[0][107]=a01;
  a13=(a06*a34);
  a09=(a01*a43);
  a13=(a13-a09);
  if (res[0]!=0) res[0][108]=a13;
  a13=(a01*a24);
  a09=(a15*a34);
  a13=(a13-a09);
  if (res[0]!=0) res[0][109]=a13;
  a13=(a15*a43);
  a09=(a06*a24);
  a13=(a13-a09);
  if (res[0]!=0) res[0][110]=a13;
  if (res[0]!=0) res[0][111]=a15;
  if (res[0]!=0) res[0][112]=a06;
  if (res[0]!=0) res[0][113]=a01;
  a13=(a06*a31);
  a09=(a01*a38);
  a13=(a13-a09);
  if (res[0]!=0) res[0][114]=a13;
  a13=(a01*a20);
  a09=(a15*a31);
  a13=(a13-a09);
  if (res[0]!=0) res[0][115]=a13;
  a13=(a15*a38);
  a09=(a06*a20);
  a13=(a13-a09);
  if (res[0]!=0) res[0][116]=a13;
  if (res[0]!=0) res[0][117]=a15;
  if (res[0]!=0) res[0][118]=a06;
  if (res[0]!=0) res[0][119]=a01;
  if (res[0]!=0) res[0][120]=a14;
  if (res[0]!=0) res[0][121]=a14;
  if (res[0]!=0) res[0][122]=a14;
  if (res[0]!=0) res[0][123]=a08;
  if (res[0]!=0) res[0][124]=a07;
  if (res[0]!=0) res[0][125]=a00;
  a01=(a07*a12);
  a06=(a00*a05);
  a01=(a01-a06);
  if (res[0]!=0) res[0][126]=a01;
  a01=(a00*a03);
  a12=(a08*a12);
  a01=(a01-a12);
  if (res[0]!=0) res[0][127]=a01;
  a05=(a08*a05);
  a03=(a07*a03);
  a05=(a05-a03);
  if (res[0]!=0) res[0][128]=a05;
  if (res[0]!=0) res[0][129]=a08;
  if (res[0]!=0) res[0][130]=a07;
  if (res[0]!=0) res[0][131]=a00;
  a05=(a07*a34);
  a03=(a00*a43);
  a05=(a05-a03);
  if (res[0]!=0) res[0][132]=a05;
  a05=(a00*a24);
  a34=(a08*a34);
  a05=(a05-a34);
  if (res[0]!=0) res[0][133]=a05;
  a43=(a08*a43);
  a24=(a07*a24);
  a43=(a43-a24);
  if (res[0]!=0) res[0][134]=a43;
  if (res[0]!=0) res[0][135]=a08;
  if (res[0]!=0) res[0][136]=a07;
  if (res[0]!=0) res[0][137]=a00;
  a43=(a07*a31);
  a24=(a00*a38);
  a43=(a43-a24);
  if (res[0]!=0) res[0][138]=a43;
  a43=(a00*a20);
  a31=(a08*a31);
  a43=(a43-a31);
  if (res[0]!=0) res[0][139]=a43;
  a38=(a08*a38);
  a20=(a07*a20);
  a38=(a38-a20);
  if (res[0]!=0) res[0][140]=a38;
  if (res[0]!=0) res[0][141]=a08;
  if (res[0]!=0) res[0][142]=a07;
  if (res[0]!=0) res[0][143]=a00;
  if (res[0]!=0) res[0][144]=a14;
  if (res[0]!=0) res[0][145]=a14;
  if (res[0]!=0) res[0][146]=a14;
  if (res[0]!=0) res[0][147]=a14;
  if (res[0]!=0) res[0][148]=a14;
  if (res[0]!=0) res[0][149]=a14;
  if (res[0]!=0) res[0][150]=a14;
  if (res[0]!=0) res[0][151]=a14;
  if (res[0]!=0) res[0][152]=a14;
  if (res[0]!=0) res[0][153]=a11;
  if (res[0]!=0) res[0][154]=a36;
  if (res[0]!=0) res[0][155]=a10;
  a00=(a36*a18);
  a07=(a10*a37);
  a00=(a00-a07);
  if (res[0]!=0) res[0][156]=a00;
  a00=(a10*a17);
  a18=(a11*a18);
  a00=(a00-a18);
  if (res[0]!=0) res[0][157]=a00;
  a37=(a11*a37);
  a17=(a36*a17);
  a37=(a37-a17);
  if (res[0]!=0) res[0][158]=a37;
  if (res[0]!=0) res[0][159]=a11;
  if (res[0]!=0) res[0][160]=a36;
  if (res[0]!=0) res[0][161]=a10;
  a33=(a33-a32);
  a32=(a36*a33);
  a42=(a42-a41);
  a41=(a10*a42);
  a32=(a32-a41);
  if (res[0]!=0) res[0][162]=a32;
  a23=(a23-a19);
  a19=(a10*a23);
  a33=(a11*a33);
  a19=(a19-a33);
  if (res[0]!=0) res[0][163]=a19;
  a42=(a11*a42);
  a23=(a36*a23);
  a42=(a42-a23);
  if (res[0]!=0) res[0][164]=a42;
  if (res[0]!=0) res[0][165]=a11;
  if (res[0]!=0) res[0][166]=a36;
  if (res[0]!=0) res[0][167]=a10;
  if (res[0]!=0) res[0][168]=a14;
  if (res[0]!=0) res[0][169]=a14;
  if (res[0]!=0) res[0][170]=a14;
  if (res[0]!=0) res[0][171]=a14;
  if (res[0]!=0) res[0][172]=a14;
  if (res[0]!=0) res[0][173]=a14;
  if (res[0]!=0) res[0][174]=a14;
  if (res[0]!=0) res[0][175]=a14;
  if (res[0]!=0) res[0][176]=a14;
  if (res[0]!=0) res[0][177]=a14;
  if (res[0]!=0) res[0][178]=a14;
  if (res[0]!=0) res[0][179]=a14;
  if (res[0]!=0) res[0][180]=a14;
  if (res[0]!=0) res[0][181]=a14;
  if (res[0]!=0) res[0][182]=a14;
  if (res[0]!=0) res[0][183]=a30;
  if (res[0]!=0) res[0][184]=a54;
  if (res[0]!=0) res[0][185]=a29;
  a10=(a54*a02);
  a36=(a29*a55);
  a10=(a10-a36);
  if (res[0]!=0) res[0][186]=a10;
  a10=(a29*a16);
  a02=(a30*a02);
  a10=(a10-a02);
  if (res[0]!=0) res[0][187]=a10;
  a55=(a30*a55);
  a16=(a54*a16);
  a55=(a55-a16);
  if (res[0]!=0) res[0][188]=a55;
  if (res[0]!=0) res[0][189]=a30;
  if (res[0]!=0) res[0][190]=a54;
  if (res[0]!=0) res[0][191]=a29;
  if (res[0]!=0) res[0][192]=a14;
  if (res[0]!=0) res[0][193]=a14;
  if (res[0]!=0) res[0][194]=a14;
  if (res[0]!=0) res[0][195]=a14;
  if (res[0]!=0) res[0][196]=a14;
  if (res[0]!=0) res[0][197]=a14;
  if (res[0]!=0) res[0][198]=a14;
  if (res[0]!=0) res[0][199]=a14;
  if (res[0]!=0) res[0][200]=a14;
  if (res[0]!=0) res[0][201]=a14;
  if (res[0]!=0) res[0][202]=a14;
  if (res[0]!=0) res[0][203]=a14;
  if (res[0]!=0) res[0][204]=a14;
  if (res[0]!=0) res[0][205]=a14;
  if (res[0]!=0) res[0][206]=a14;
  if (res[0]!=0) res[0][207]=a14;
  if (res[0]!=0) res[0][208]=a14;
  if (res[0]!=0) res[0][209]=a14;
  if (res[0]!=0) res[0][210]=a14;
  if (res[0]!=0) res[0][211]=a14;
  if (res[0]!=0) res[0][212]=a14;
  a14=arg[1]? arg[1][123] : 0;
  a30=(a30*a14);
  a55=arg[1]? arg[1][121] : 0;
  a46=(a55*a46);
  a30=(a30+a46);
  a46=arg[1]? arg[1][122] : 0;
  a50=(a46*a50);
  a30=(a30+a50);
  if (res[0]!=0) res[0][213]=a30;
  a54=(a54*a14);
  a57=(a55*a57);
  a54=(a54+a57);
  a58=(a46*a58);
  a54=(a54+a58);
  if (res[0]!=0) res[0][214]=a54;
  a29=(a29*a14);
  a55=(a55*a49);
  a29=(a29+a55);
  a46=(a46*a51);
  a29=(a29+a46);
  if (res[0]!=0) res[0][215]=a29;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_jacobians(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_jacobians_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_jacobians_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_jacobians_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_link_jacobians_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_link_jacobians_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_link_jacobians_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp3_link_jacobians_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_link_jacobians_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_link_jacobians_name_out(casadi_int i) {
  switch (i) {
    case 0: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_link_jacobians_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_link_jacobians_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_jacobians_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_link_jacobians_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

/* snakecg_sp3_link_jacobians_sincos: 602 CasADi instructions, printed one per line */
static void snakecg_sp3_link_jacobians_sincos(
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
  casadi_real w50, w51, w52, w53, w54, w55, w56, w57, w58;
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
  res0[0] = w4;
  w7 = arg0[6];
  w8 = w7 + w7;
  w9 = w8 * w5;
  w10 = arg0[3];
  w11 = w10 + w10;
  w12 = w11 * w2;
  w9 = w9 + w12;
  res0[1] = w9;
  w7 = w1 * w7;
  w13 = w7 * w2;
  w11 = w11 * w5;
  w13 = w13 + w11;
  res0[2] = w13;
  w14 = 0.0;
  res0[3] = w14;
  res0[4] = w14;
  res0[5] = w14;
  res0[6] = w4;
  res0[7] = w9;
  res0[8] = w13;
  res0[9] = w14;
  res0[10] = w14;
  res0[11] = w14;
  res0[12] = w4;
  res0[13] = w9;
  res0[14] = w13;
  res0[15] = w14;
  res0[16] = w14;
  res0[17] = w14;
  res0[18] = w4;
  res0[19] = w9;
  res0[20] = w13;
  res0[21] = w14;
  res0[22] = w14;
  res0[23] = w14;
  w15 = w7 * w5;
  w15 = w15 + w12;
  res0[24] = w15;
  w12 = w10 * w10;
  w1 = w1 * w12;
  w0 = w0 + w1;
  w6 = w0 + w6;
  res0[25] = w6;
  w1 = w8 * w10;
  w12 = w2 + w2;
  w12 = w12 * w5;
  w1 = w1 + w12;
  res0[26] = w1;
  res0[27] = w14;
  res0[28] = w14;
  res0[29] = w14;
  res0[30] = w15;
  res0[31] = w6;
  res0[32] = w1;
  res0[33] = w14;
  res0[34] = w14;
  res0[35] = w14;
  res0[36] = w15;
  res0[37] = w6;
  res0[38] = w1;
  res0[39] = w14;
  res0[40] = w14;
  res0[41] = w14;
  res0[42] = w15;
  res0[43] = w6;
  res0[44] = w1;
  res0[45] = w14;
  res0[46] = w14;
  res0[47] = w14;
  w8 = w8 * w2;
  w8 = w8 + w11;
  res0[48] = w8;
  w7 = w7 * w10;
  w7 = w7 + w12;
  res0[49] = w7;
  w0 = w0 + w3;
  res0[50] = w0;
  res0[51] = w14;
  res0[52] = w14;
  res0[53] = w14;
  res0[54] = w8;
  res0[55] = w7;
  res0[56] = w0;
  res0[57] = w14;
  res0[58] = w14;
  res0[59] = w14;
  res0[60] = w8;
  res0[61] = w7;
  res0[62] = w0;
  res0[63] = w14;
  res0[64] = w14;
  res0[65] = w14;
  res0[66] = w8;
  res0[67] = w7;
  res0[68] = w0;
  res0[69] = w14;
  res0[70] = w14;
  res0[71] = w14;
  res0[72] = w14;
  res0[73] = w14;
  res0[74] = w14;
  res0[75] = w4;
  res0[76] = w9;
  res0[77] = w13;
  w3 = arg1[124];
  w12 = w13 * w3;
  w10 = arg1[125];
  w11 = w1 * w10;
  w12 = w12 + w11;
  w11 = arg1[126];
  w2 = w0 * w11;
  w12 = w12 + w2;
  w2 = w9 * w12;
  w5 = w9 * w3;
  w16 = w6 * w10;
  w5 = w5 + w16;
  w16 = w7 * w11;
  w5 = w5 + w16;
  w16 = w13 * w5;
  w2 = w2 - w16;
  res0[78] = w2;
  w3 = w4 * w3;
  w10 = w15 * w10;
  w3 = w3 + w10;
  w11 = w8 * w11;
  w3 = w3 + w11;
  w11 = w13 * w3;
  w10 = w4 * w12;
  w11 = w11 - w10;
  res0[79] = w11;
  w11 = w4 * w5;
  w10 = w9 * w3;
  w11 = w11 - w10;
  res0[80] = w11;
  res0[81] = w4;
  res0[82] = w9;
  res0[83] = w13;
  w11 = arg1[103];
  w10 = w11 * w13;
  w2 = arg1[104];
  w16 = w2 * w1;
  w10 = w10 + w16;
  w16 = arg1[105];
  w17 = w16 * w0;
  w10 = w10 + w17;
  w17 = arg1[129];
  w18 = w10 * w17;
  w19 = arg1[97];
  w20 = w19 * w13;
  w21 = arg1[98];
  w22 = w21 * w1;
  w20 = w20 + w22;
  w22 = arg1[99];
  w23 = w22 * w0;
  w20 = w20 + w23;
  w23 = arg2[0];
  w24 = w20 * w23;
  w25 = arg1[100];
  w26 = w25 * w13;
  w27 = arg1[101];
  w28 = w27 * w1;
  w26 = w26 + w28;
  w28 = arg1[102];
  w29 = w28 * w0;
  w26 = w26 + w29;
  w29 = arg3[0];
  w30 = w26 * w29;
  w24 = w24 + w30;
  w30 = arg1[127];
  w31 = w24 * w30;
  w18 = w18 + w31;
  w26 = w26 * w23;
  w20 = w20 * w29;
  w26 = w26 - w20;
  w20 = arg1[128];
  w31 = w26 * w20;
  w18 = w18 + w31;
  w31 = arg0[2];
  w32 = w12 + w31;
  w33 = w18 + w32;
  w34 = w33 - w31;
  w35 = w9 * w34;
  w36 = w11 * w9;
  w37 = w2 * w6;
  w36 = w36 + w37;
  w37 = w16 * w7;
  w36 = w36 + w37;
  w37 = w36 * w17;
  w38 = w19 * w9;
  w39 = w21 * w6;
  w38 = w38 + w39;
  w39 = w22 * w7;
  w38 = w38 + w39;
  w39 = w38 * w23;
  w40 = w25 * w9;
  w41 = w27 * w6;
  w40 = w40 + w41;
  w41 = w28 * w7;
  w40 = w40 + w41;
  w41 = w40 * w29;
  w39 = w39 + w41;
  w41 = w39 * w30;
  w37 = w37 + w41;
  w40 = w40 * w23;
  w38 = w38 * w29;
  w40 = w40 - w38;
  w38 = w40 * w20;
  w37 = w37 + w38;
  w38 = arg0[1];
  w41 = w5 + w38;
  w42 = w37 + w41;
  w43 = w42 - w38;
  w44 = w13 * w43;
  w35 = w35 - w44;
  res0[84] = w35;
  w11 = w11 * w4;
  w2 = w2 * w15;
  w11 = w11 + w2;
  w16 = w16 * w8;
  w11 = w11 + w16;
  w17 = w11 * w17;
  w19 = w19 * w4;
  w21 = w21 * w15;
  w19 = w19 + w21;
  w22 = w22 * w8;
  w19 = w19 + w22;
  w22 = w19 * w23;
  w25 = w25 * w4;
  w27 = w27 * w15;
  w25 = w25 + w27;
  w28 = w28 * w8;
  w25 = w25 + w28;
  w28 = w25 * w29;
  w22 = w22 + w28;
  w30 = w22 * w30;
  w17 = w17 + w30;
  w25 = w25 * w23;
  w19 = w19 * w29;
  w25 = w25 - w19;
  w20 = w25 * w20;
  w17 = w17 + w20;
  w20 = arg0[0];
  w19 = w3 + w20;
  w29 = w17 + w19;
  w23 = w29 - w20;
  w30 = w13 * w23;
  w28 = w4 * w34;
  w30 = w30 - w28;
  res0[85] = w30;
  w30 = w4 * w43;
  w28 = w9 * w23;
  w30 = w30 - w28;
  res0[86] = w30;
  res0[87] = w4;
  res0[88] = w9;
  res0[89] = w13;
  w30 = arg1[114];
  w28 = w10 * w30;
  w27 = arg1[112];
  w21 = w27 * w24;
  w28 = w28 + w21;
  w21 = arg1[113];
  w16 = w21 * w26;
  w28 = w28 + w16;
  w16 = arg1[132];
  w2 = w28 * w16;
  w35 = arg1[108];
  w44 = w10 * w35;
  w45 = arg1[106];
  w46 = w45 * w24;
  w44 = w44 + w46;
  w46 = arg1[107];
  w47 = w46 * w26;
  w44 = w44 + w47;
  w47 = arg2[1];
  w48 = w44 * w47;
  w49 = arg1[111];
  w50 = w10 * w49;
  w51 = arg1[109];
  w24 = w51 * w24;
  w50 = w50 + w24;
  w24 = arg1[110];
  w26 = w24 * w26;
  w50 = w50 + w26;
  w26 = arg3[1];
  w52 = w50 * w26;
  w48 = w48 + w52;
  w52 = arg1[130];
  w53 = w48 * w52;
  w2 = w2 + w53;
  w50 = w50 * w47;
  w44 = w44 * w26;
  w50 = w50 - w44;
  w44 = arg1[131];
  w53 = w50 * w44;
  w2 = w2 + w53;
  w33 = w2 + w33;
  w31 = w33 - w31;
  w53 = w9 * w31;
  w54 = w36 * w30;
  w55 = w27 * w39;
  w54 = w54 + w55;
  w55 = w21 * w40;
  w54 = w54 + w55;
  w55 = w54 * w16;
  w56 = w36 * w35;
  w57 = w45 * w39;
  w56 = w56 + w57;
  w57 = w46 * w40;
  w56 = w56 + w57;
  w57 = w56 * w47;
  w58 = w36 * w49;
  w39 = w51 * w39;
  w58 = w58 + w39;
  w40 = w24 * w40;
  w58 = w58 + w40;
  w40 = w58 * w26;
  w57 = w57 + w40;
  w40 = w57 * w52;
  w55 = w55 + w40;
  w58 = w58 * w47;
  w56 = w56 * w26;
  w58 = w58 - w56;
  w56 = w58 * w44;
  w55 = w55 + w56;
  w42 = w55 + w42;
  w38 = w42 - w38;
  w56 = w13 * w38;
  w53 = w53 - w56;
  res0[90] = w53;
  w30 = w11 * w30;
  w27 = w27 * w22;
  w30 = w30 + w27;
  w21 = w21 * w25;
  w30 = w30 + w21;
  w16 = w30 * w16;
  w35 = w11 * w35;
  w45 = w45 * w22;
  w35 = w35 + w45;
  w46 = w46 * w25;
  w35 = w35 + w46;
  w46 = w35 * w47;
  w49 = w11 * w49;
  w51 = w51 * w22;
  w49 = w49 + w51;
  w24 = w24 * w25;
  w49 = w49 + w24;
  w24 = w49 * w26;
  w46 = w46 + w24;
  w52 = w46 * w52;
  w16 = w16 + w52;
  w49 = w49 * w47;
  w35 = w35 * w26;
  w49 = w49 - w35;
  w44 = w49 * w44;
  w16 = w16 + w44;
  w29 = w16 + w29;
  w20 = w29 - w20;
  w44 = w13 * w20;
  w35 = w4 * w31;
  w44 = w44 - w35;
  res0[91] = w44;
  w44 = w4 * w38;
  w35 = w9 * w20;
  w44 = w44 - w35;
  res0[92] = w44;
  res0[93] = w4;
  res0[94] = w9;
  res0[95] = w13;
  res0[96] = w14;
  res0[97] = w14;
  res0[98] = w14;
  res0[99] = w15;
  res0[100] = w6;
  res0[101] = w1;
  w13 = w6 * w12;
  w9 = w1 * w5;
  w13 = w13 - w9;
  res0[102] = w13;
  w13 = w1 * w3;
  w9 = w15 * w12;
  w13 = w13 - w9;
  res0[103] = w13;
  w13 = w15 * w5;
  w9 = w6 * w3;
  w13 = w13 - w9;
  res0[104] = w13;
  res0[105] = w15;
  res0[106] = w6;
  res0[107] = w1;
  w13 = w6 * w34;
  w9 = w1 * w43;
  w13 = w13 - w9;
  res0[108] = w13;
  w13 = w1 * w23;
  w9 = w15 * w34;
  w13 = w13 - w9;
  res0[109] = w13;
  w13 = w15 * w43;
  w9 = w6 * w23;
  w13 = w13 - w9;
  res0[110] = w13;
  res0[111] = w15;
  res0[112] = w6;
  res0[113] = w1;
  w13 = w6 * w31;
  w9 = w1 * w38;
  w13 = w13 - w9;
  res0[114] = w13;
  w13 = w1 * w20;
  w9 = w15 * w31;
  w13 = w13 - w9;
  res0[115] = w13;
  w13 = w15 * w38;
  w9 = w6 * w20;
  w13 = w13 - w9;
  res0[116] = w13;
  res0[117] = w15;
  res0[118] = w6;
  res0[119] = w1;
  res0[120] = w14;
  res0[121] = w14;
  res0[122] = w14;
  res0[123] = w8;
  res0[124] = w7;
  res0[125] = w0;
  w1 = w7 * w12;
  w6 = w0 * w5;
  w1 = w1 - w6;
  res0[126] = w1;
  w1 = w0 * w3;
  w12 = w8 * w12;
  w1 = w1 - w12;
  res0[127] = w1;
  w5 = w8 * w5;
  w3 = w7 * w3;
  w5 = w5 - w3;
  res0[128] = w5;
  res0[129] = w8;
  res0[130] = w7;
  res0[131] = w0;
  w5 = w7 * w34;
  w3 = w0 * w43;
  w5 = w5 - w3;
  res0[132] = w5;
  w5 = w0 * w23;
  w34 = w8 * w34;
  w5 = w5 - w34;
  res0[133] = w5;
  w43 = w8 * w43;
  w23 = w7 * w23;
  w43 = w43 - w23;
  res0[134] = w43;
  res0[135] = w8;
  res0[136] = w7;
  res0[137] = w0;
  w43 = w7 * w31;
  w23 = w0 * w38;
  w43 = w43 - w23;
  res0[138] = w43;
  w43 = w0 * w20;
  w31 = w8 * w31;
  w43 = w43 - w31;
  res0[139] = w43;
  w38 = w8 * w38;
  w20 = w7 * w20;
  w38 = w38 - w20;
  res0[140] = w38;
  res0[141] = w8;
  res0[142] = w7;
  res0[143] = w0;
  res0[144] = w14;
  res0[145] = w14;
  res0[146] = w14;
  res0[147] = w14;
  res0[148] = w14;
  res0[149] = w14;
  res0[150] = w14;
  res0[151] = w14;
  res0[152] = w14;
  res0[153] = w11;
  res0[154] = w36;
  res0[155] = w10;
  w0 = w36 * w18;
  w7 = w10 * w37;
  w0 = w0 - w7;
  res0[156] = w0;
  w0 = w10 * w17;
  w18 = w11 * w18;
  w0 = w0 - w18;
  res0[157] = w0;
  w37 = w11 * w37;
  w17 = w36 * w17;
  w37 = w37 - w17;
  res0[158] = w37;
  res0[159] = w11;
  res0[160] = w36;
  res0[161] = w10;
  w33 = w33 - w32;
  w32 = w36 * w33;
  w42 = w42 - w41;
  w41 = w10 * w42;
  w32 = w32 - w41;
  res0[162] = w32;
  w29 = w29 - w19;
  w19 = w10 * w29;
  w33 = w11 * w33;
  w19 = w19 - w33;
  res0[163] = w19;
  w42 = w11 * w42;
  w29 = w36 * w29;
  w42 = w42 - w29;
  res0[164] = w42;
  res0[165] = w11;
  res0[166] = w36;
  res0[167] = w10;
  res0[168] = w14;
  res0[169] = w14;
  res0[170] = w14;
  res0[171] = w14;
  res0[172] = w14;
  res0[173] = w14;
  res0[174] = w14;
  res0[175] = w14;
  res0[176] = w14;
  res0[177] = w14;
  res0[178] = w14;
  res0[179] = w14;
  res0[180] = w14;
  res0[181] = w14;
  res0[182] = w14;
  res0[183] = w30;
  res0[184] = w54;
  res0[185] = w28;
  w10 = w54 * w2;
  w36 = w28 * w55;
  w10 = w10 - w36;
  res0[186] = w10;
  w10 = w28 * w16;
  w2 = w30 * w2;
  w10 = w10 - w2;
  res0[187] = w10;
  w55 = w30 * w55;
  w16 = w54 * w16;
  w55 = w55 - w16;
  res0[188] = w55;
  res0[189] = w30;
  res0[190] = w54;
  res0[191] = w28;
  res0[192] = w14;
  res0[193] = w14;
  res0[194] = w14;
  res0[195] = w14;
  res0[196] = w14;
  res0[197] = w14;
  res0[198] = w14;
  res0[199] = w14;
  res0[200] = w14;
  res0[201] = w14;
  res0[202] = w14;
  res0[203] = w14;
  res0[204] = w14;
  res0[205] = w14;
  res0[206] = w14;
  res0[207] = w14;
  res0[208] = w14;
  res0[209] = w14;
  res0[210] = w14;
  res0[211] = w14;
  res0[212] = w14;
  w14 = arg1[123];
  w30 = w30 * w14;
  w55 = arg1[121];
  w46 = w55 * w46;
  w30 = w30 + w46;
  w46 = arg1[122];
  w49 = w46 * w49;
  w30 = w30 + w49;
  res0[213] = w30;
  w54 = w54 * w14;
  w57 = w55 * w57;
  w54 = w54 + w57;
  w58 = w46 * w58;
  w54 = w54 + w58;
  res0[214] = w54;
  w28 = w28 * w14;
  w55 = w55 * w48;
  w28 = w28 + w55;
  w46 = w46 * w50;
  w28 = w28 + w46;
  res0[215] = w28;
}


CASADI_SYMBOL_EXPORT int snakecg_sp3_batch_link_jacobians(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 60);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && res[0]) {
    /* cos and sin of q[7..9] of 16 samples at a time, then snakecg_sp3_link_jacobians_sincos
     * per sample (a batch of one too, so that a batch equals its samples one by one) */
    const casadi_int na = 3, per = 16;
    casadi_real ang[48], ca[48], sa[48];
    casadi_int i0, m;
    int large;
    for (k = 0; k < 48; ++k) ang[k] = 0;
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
        snakecg_sp3_link_jacobians_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], ca + i * na, sa + i * na, res[0] + (i0 + i) * 216);
      }
    }
  } else {
    /* a null input or output (CasADi's convention: zeros in, nothing out): per sample */
    for (i = 0; i < n; ++i) {
      a[0] = arg[0] + i * stride[0];
      a[1] = arg[1] + i * stride[1];
      r[0] = res[0] + i * 216;
      if (snakecg_sp3_link_jacobians(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
