/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for point_jacobian() of
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
  #define CASADI_PREFIX(ID) snakecg_sp3_point_jacobian_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp3_point_jacobian_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp3_point_jacobian_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp3_point_jacobian_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {10, 1, 1};
static const casadi_int casadi_s1[3] = {169, 1, 1};
static const casadi_int casadi_s2[3] = {4, 1, 1};
static const casadi_int casadi_s3[3] = {3, 1, 1};
static const casadi_int casadi_s4[3] = {3, 9, 1};

/* snakecg_sp3_point_jacobian:(q[10],K[169],link[4],point[3])->(position[3],J[3x9]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82;
  a00=arg[1]? arg[1][97] : 0;
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
  a09=arg[1]? arg[1][98] : 0;
  a10=arg[0]? arg[0][6] : 0;
  a11=(a02*a10);
  a12=(a11*a06);
  a13=arg[0]? arg[0][3] : 0;
  a14=(2.*a13);
  a15=(a14*a03);
  a12=(a12+a15);
  a16=(a09*a12);
  a08=(a08+a16);
  a16=arg[1]? arg[1][99] : 0;
  a10=(2.*a10);
  a17=(a10*a03);
  a14=(a14*a06);
  a17=(a17+a14);
  a18=(a16*a17);
  a08=(a08+a18);
  a18=arg[0]? arg[0][7] : 0;
  a19=cos(a18);
  a20=(a08*a19);
  a21=arg[1]? arg[1][100] : 0;
  a22=(a21*a05);
  a23=arg[1]? arg[1][101] : 0;
  a24=(a23*a12);
  a22=(a22+a24);
  a24=arg[1]? arg[1][102] : 0;
  a25=(a24*a17);
  a22=(a22+a25);
  a18=sin(a18);
  a25=(a22*a18);
  a20=(a20+a25);
  a25=arg[2]? arg[2][1] : 0;
  a26=(a20*a25);
  a27=arg[1]? arg[1][103] : 0;
  a28=(a27*a05);
  a29=arg[1]? arg[1][104] : 0;
  a30=(a29*a12);
  a28=(a28+a30);
  a30=arg[1]? arg[1][105] : 0;
  a31=(a30*a17);
  a28=(a28+a31);
  a31=arg[1]? arg[1][108] : 0;
  a32=(a28*a31);
  a33=arg[1]? arg[1][106] : 0;
  a34=(a33*a20);
  a32=(a32+a34);
  a34=arg[1]? arg[1][107] : 0;
  a22=(a22*a19);
  a08=(a08*a18);
  a22=(a22-a08);
  a08=(a34*a22);
  a32=(a32+a08);
  a08=arg[0]? arg[0][8] : 0;
  a35=cos(a08);
  a36=(a32*a35);
  a37=arg[1]? arg[1][111] : 0;
  a38=(a28*a37);
  a39=arg[1]? arg[1][109] : 0;
  a40=(a39*a20);
  a38=(a38+a40);
  a40=arg[1]? arg[1][110] : 0;
  a41=(a40*a22);
  a38=(a38+a41);
  a08=sin(a08);
  a41=(a38*a08);
  a36=(a36+a41);
  a41=arg[2]? arg[2][2] : 0;
  a42=(a36*a41);
  a26=(a26+a42);
  a42=arg[1]? arg[1][114] : 0;
  a43=(a28*a42);
  a44=arg[1]? arg[1][112] : 0;
  a45=(a44*a20);
  a43=(a43+a45);
  a45=arg[1]? arg[1][113] : 0;
  a46=(a45*a22);
  a43=(a43+a46);
  a46=arg[1]? arg[1][117] : 0;
  a47=(a43*a46);
  a48=arg[1]? arg[1][115] : 0;
  a49=(a48*a36);
  a47=(a47+a49);
  a49=arg[1]? arg[1][116] : 0;
  a38=(a38*a35);
  a32=(a32*a08);
  a38=(a38-a32);
  a32=(a49*a38);
  a47=(a47+a32);
  a32=arg[0]? arg[0][9] : 0;
  a50=cos(a32);
  a51=(a47*a50);
  a52=arg[1]? arg[1][120] : 0;
  a53=(a43*a52);
  a54=arg[1]? arg[1][118] : 0;
  a55=(a54*a36);
  a53=(a53+a55);
  a55=arg[1]? arg[1][119] : 0;
  a56=(a55*a38);
  a53=(a53+a56);
  a32=sin(a32);
  a56=(a53*a32);
  a51=(a51+a56);
  a56=arg[2]? arg[2][3] : 0;
  a51=(a51*a56);
  a26=(a26+a51);
  a51=arg[2]? arg[2][0] : 0;
  a57=(a05*a51);
  a26=(a26+a57);
  a57=arg[1]? arg[1][70] : 0;
  a57=(a57*a25);
  a57=(a51+a57);
  a58=arg[1]? arg[1][79] : 0;
  a58=(a58*a41);
  a57=(a57+a58);
  a58=arg[1]? arg[1][88] : 0;
  a58=(a58*a56);
  a57=(a57+a58);
  a58=arg[3]? arg[3][0] : 0;
  a57=(a57*a58);
  a59=arg[1]? arg[1][71] : 0;
  a59=(a59*a25);
  a60=arg[1]? arg[1][80] : 0;
  a60=(a60*a41);
  a59=(a59+a60);
  a60=arg[1]? arg[1][89] : 0;
  a60=(a60*a56);
  a59=(a59+a60);
  a60=arg[3]? arg[3][1] : 0;
  a59=(a59*a60);
  a57=(a57+a59);
  a59=arg[1]? arg[1][72] : 0;
  a59=(a59*a25);
  a61=arg[1]? arg[1][81] : 0;
  a61=(a61*a41);
  a59=(a59+a61);
  a61=arg[1]? arg[1][90] : 0;
  a61=(a61*a56);
  a59=(a59+a61);
  a61=arg[3]? arg[3][2] : 0;
  a59=(a59*a61);
  a57=(a57+a59);
  a26=(a26*a57);
  a59=(a22*a25);
  a62=(a38*a41);
  a59=(a59+a62);
  a53=(a53*a50);
  a47=(a47*a32);
  a53=(a53-a47);
  a53=(a53*a56);
  a59=(a59+a53);
  a53=(a12*a51);
  a59=(a59+a53);
  a53=arg[1]? arg[1][73] : 0;
  a53=(a53*a25);
  a47=arg[1]? arg[1][82] : 0;
  a47=(a47*a41);
  a53=(a53+a47);
  a47=arg[1]? arg[1][91] : 0;
  a47=(a47*a56);
  a53=(a53+a47);
  a53=(a53*a58);
  a47=arg[1]? arg[1][74] : 0;
  a47=(a47*a25);
  a47=(a51+a47);
  a62=arg[1]? arg[1][83] : 0;
  a62=(a62*a41);
  a47=(a47+a62);
  a62=arg[1]? arg[1][92] : 0;
  a62=(a62*a56);
  a47=(a47+a62);
  a47=(a47*a60);
  a53=(a53+a47);
  a47=arg[1]? arg[1][75] : 0;
  a47=(a47*a25);
  a62=arg[1]? arg[1][84] : 0;
  a62=(a62*a41);
  a47=(a47+a62);
  a62=arg[1]? arg[1][93] : 0;
  a62=(a62*a56);
  a47=(a47+a62);
  a47=(a47*a61);
  a53=(a53+a47);
  a59=(a59*a53);
  a26=(a26+a59);
  a59=(a28*a25);
  a47=(a43*a41);
  a59=(a59+a47);
  a47=arg[1]? arg[1][123] : 0;
  a62=(a43*a47);
  a63=arg[1]? arg[1][121] : 0;
  a64=(a63*a36);
  a62=(a62+a64);
  a64=arg[1]? arg[1][122] : 0;
  a65=(a64*a38);
  a62=(a62+a65);
  a65=(a62*a56);
  a59=(a59+a65);
  a65=(a17*a51);
  a59=(a59+a65);
  a65=arg[1]? arg[1][76] : 0;
  a65=(a65*a25);
  a66=arg[1]? arg[1][85] : 0;
  a66=(a66*a41);
  a65=(a65+a66);
  a66=arg[1]? arg[1][94] : 0;
  a66=(a66*a56);
  a65=(a65+a66);
  a65=(a65*a58);
  a58=arg[1]? arg[1][77] : 0;
  a58=(a58*a25);
  a66=arg[1]? arg[1][86] : 0;
  a66=(a66*a41);
  a58=(a58+a66);
  a66=arg[1]? arg[1][95] : 0;
  a66=(a66*a56);
  a58=(a58+a66);
  a58=(a58*a60);
  a65=(a65+a58);
  a58=arg[1]? arg[1][78] : 0;
  a58=(a58*a25);
  a58=(a51+a58);
  a60=arg[1]? arg[1][87] : 0;
  a60=(a60*a41);
  a58=(a58+a60);
  a60=arg[1]? arg[1][96] : 0;
  a60=(a60*a56);
  a58=(a58+a60);
  a58=(a58*a61);
  a65=(a65+a58);
  a59=(a59*a65);
  a26=(a26+a59);
  a59=arg[1]? arg[1][124] : 0;
  a58=(a05*a59);
  a61=arg[1]? arg[1][125] : 0;
  a60=(a12*a61);
  a58=(a58+a60);
  a60=arg[1]? arg[1][126] : 0;
  a66=(a17*a60);
  a58=(a58+a66);
  a66=arg[0]? arg[0][0] : 0;
  a58=(a58+a66);
  a67=(a58*a25);
  a68=arg[1]? arg[1][129] : 0;
  a69=(a28*a68);
  a70=arg[1]? arg[1][127] : 0;
  a20=(a20*a70);
  a69=(a69+a20);
  a20=arg[1]? arg[1][128] : 0;
  a22=(a22*a20);
  a69=(a69+a22);
  a69=(a69+a58);
  a22=(a69*a41);
  a67=(a67+a22);
  a22=arg[1]? arg[1][132] : 0;
  a71=(a43*a22);
  a72=arg[1]? arg[1][130] : 0;
  a36=(a36*a72);
  a71=(a71+a36);
  a36=arg[1]? arg[1][131] : 0;
  a38=(a38*a36);
  a71=(a71+a38);
  a71=(a71+a69);
  a38=(a71*a56);
  a67=(a67+a38);
  a38=(a51*a66);
  a67=(a67+a38);
  a26=(a26+a67);
  if (res[0]!=0) res[0][0]=a26;
  a67=(a10*a06);
  a67=(a67+a15);
  a15=(a00*a67);
  a38=casadi_sq(a13);
  a02=(a02*a38);
  a01=(a01+a02);
  a07=(a01+a07);
  a02=(a09*a07);
  a15=(a15+a02);
  a02=(a11*a13);
  a38=(2.*a03);
  a38=(a38*a06);
  a02=(a02+a38);
  a06=(a16*a02);
  a15=(a15+a06);
  a06=(a15*a19);
  a73=(a21*a67);
  a74=(a23*a07);
  a73=(a73+a74);
  a74=(a24*a02);
  a73=(a73+a74);
  a74=(a73*a18);
  a06=(a06+a74);
  a74=(a06*a25);
  a75=(a27*a67);
  a76=(a29*a07);
  a75=(a75+a76);
  a76=(a30*a02);
  a75=(a75+a76);
  a76=(a75*a31);
  a77=(a33*a06);
  a76=(a76+a77);
  a73=(a73*a19);
  a15=(a15*a18);
  a73=(a73-a15);
  a15=(a34*a73);
  a76=(a76+a15);
  a15=(a76*a35);
  a77=(a75*a37);
  a78=(a39*a06);
  a77=(a77+a78);
  a78=(a40*a73);
  a77=(a77+a78);
  a78=(a77*a08);
  a15=(a15+a78);
  a78=(a15*a41);
  a74=(a74+a78);
  a78=(a75*a42);
  a79=(a44*a06);
  a78=(a78+a79);
  a79=(a45*a73);
  a78=(a78+a79);
  a79=(a78*a46);
  a80=(a48*a15);
  a79=(a79+a80);
  a77=(a77*a35);
  a76=(a76*a08);
  a77=(a77-a76);
  a76=(a49*a77);
  a79=(a79+a76);
  a76=(a79*a50);
  a80=(a78*a52);
  a81=(a54*a15);
  a80=(a80+a81);
  a81=(a55*a77);
  a80=(a80+a81);
  a81=(a80*a32);
  a76=(a76+a81);
  a76=(a76*a56);
  a74=(a74+a76);
  a76=(a67*a51);
  a74=(a74+a76);
  a74=(a74*a57);
  a76=(a73*a25);
  a81=(a77*a41);
  a76=(a76+a81);
  a80=(a80*a50);
  a79=(a79*a32);
  a80=(a80-a79);
  a80=(a80*a56);
  a76=(a76+a80);
  a80=(a07*a51);
  a76=(a76+a80);
  a76=(a76*a53);
  a74=(a74+a76);
  a76=(a75*a25);
  a80=(a78*a41);
  a76=(a76+a80);
  a80=(a78*a47);
  a79=(a63*a15);
  a80=(a80+a79);
  a79=(a64*a77);
  a80=(a80+a79);
  a79=(a80*a56);
  a76=(a76+a79);
  a79=(a02*a51);
  a76=(a76+a79);
  a76=(a76*a65);
  a74=(a74+a76);
  a76=(a67*a59);
  a79=(a07*a61);
  a76=(a76+a79);
  a79=(a02*a60);
  a76=(a76+a79);
  a79=arg[0]? arg[0][1] : 0;
  a76=(a76+a79);
  a81=(a76*a25);
  a82=(a75*a68);
  a06=(a06*a70);
  a82=(a82+a06);
  a73=(a73*a20);
  a82=(a82+a73);
  a82=(a82+a76);
  a73=(a82*a41);
  a81=(a81+a73);
  a73=(a78*a22);
  a15=(a15*a72);
  a73=(a73+a15);
  a77=(a77*a36);
  a73=(a73+a77);
  a73=(a73+a82);
  a77=(a73*a56);
  a81=(a81+a77);
  a77=(a51*a79);
  a81=(a81+a77);
  a74=(a74+a81);
  if (res[0]!=0) res[0][1]=a74;
  a11=(a11*a03);
  a11=(a11+a14);
  a00=(a00*a11);
  a10=(a10*a13);
  a10=(a10+a38);
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
  a40=(a34*a41);
  a24=(a24+a40);
  a42=(a27*a42);
  a44=(a44*a16);
  a42=(a42+a44);
  a45=(a45*a21);
  a42=(a42+a45);
  a46=(a42*a46);
  a48=(a48*a34);
  a46=(a46+a48);
  a37=(a37*a35);
  a31=(a31*a08);
  a37=(a37-a31);
  a49=(a49*a37);
  a46=(a46+a49);
  a49=(a46*a50);
  a52=(a42*a52);
  a54=(a54*a34);
  a52=(a52+a54);
  a55=(a55*a37);
  a52=(a52+a55);
  a55=(a52*a32);
  a49=(a49+a55);
  a49=(a49*a56);
  a24=(a24+a49);
  a49=(a11*a51);
  a24=(a24+a49);
  a24=(a24*a57);
  a57=(a21*a25);
  a49=(a37*a41);
  a57=(a57+a49);
  a52=(a52*a50);
  a46=(a46*a32);
  a52=(a52-a46);
  a52=(a52*a56);
  a57=(a57+a52);
  a52=(a10*a51);
  a57=(a57+a52);
  a57=(a57*a53);
  a24=(a24+a57);
  a57=(a27*a25);
  a53=(a42*a41);
  a57=(a57+a53);
  a47=(a42*a47);
  a63=(a63*a34);
  a47=(a47+a63);
  a64=(a64*a37);
  a47=(a47+a64);
  a64=(a47*a56);
  a57=(a57+a64);
  a64=(a01*a51);
  a57=(a57+a64);
  a57=(a57*a65);
  a24=(a24+a57);
  a59=(a11*a59);
  a61=(a10*a61);
  a59=(a59+a61);
  a60=(a01*a60);
  a59=(a59+a60);
  a60=arg[0]? arg[0][2] : 0;
  a59=(a59+a60);
  a61=(a59*a25);
  a68=(a27*a68);
  a16=(a16*a70);
  a68=(a68+a16);
  a21=(a21*a20);
  a68=(a68+a21);
  a68=(a68+a59);
  a21=(a68*a41);
  a61=(a61+a21);
  a22=(a42*a22);
  a34=(a34*a72);
  a22=(a22+a34);
  a37=(a37*a36);
  a22=(a22+a37);
  a22=(a22+a68);
  a37=(a22*a56);
  a61=(a61+a37);
  a51=(a51*a60);
  a61=(a61+a51);
  a24=(a24+a61);
  if (res[0]!=0) res[0][2]=a24;
  if (res[1]!=0) res[1][0]=a05;
  if (res[1]!=0) res[1][1]=a67;
  if (res[1]!=0) res[1][2]=a11;
  if (res[1]!=0) res[1][3]=a12;
  if (res[1]!=0) res[1][4]=a07;
  if (res[1]!=0) res[1][5]=a10;
  if (res[1]!=0) res[1][6]=a17;
  if (res[1]!=0) res[1][7]=a02;
  if (res[1]!=0) res[1][8]=a01;
  a60=(a24-a60);
  a61=(a67*a60);
  a79=(a74-a79);
  a51=(a11*a79);
  a61=(a61-a51);
  if (res[1]!=0) res[1][9]=a61;
  a66=(a26-a66);
  a11=(a11*a66);
  a61=(a05*a60);
  a11=(a11-a61);
  if (res[1]!=0) res[1][10]=a11;
  a05=(a05*a79);
  a67=(a67*a66);
  a05=(a05-a67);
  if (res[1]!=0) res[1][11]=a05;
  a05=(a07*a60);
  a67=(a10*a79);
  a05=(a05-a67);
  if (res[1]!=0) res[1][12]=a05;
  a10=(a10*a66);
  a05=(a12*a60);
  a10=(a10-a05);
  if (res[1]!=0) res[1][13]=a10;
  a12=(a12*a79);
  a07=(a07*a66);
  a12=(a12-a07);
  if (res[1]!=0) res[1][14]=a12;
  a12=(a02*a60);
  a07=(a01*a79);
  a12=(a12-a07);
  if (res[1]!=0) res[1][15]=a12;
  a01=(a01*a66);
  a60=(a17*a60);
  a01=(a01-a60);
  if (res[1]!=0) res[1][16]=a01;
  a17=(a17*a79);
  a02=(a02*a66);
  a17=(a17-a02);
  if (res[1]!=0) res[1][17]=a17;
  a41=(a41+a56);
  a25=(a41+a25);
  a59=(a24-a59);
  a17=(a75*a59);
  a76=(a74-a76);
  a02=(a27*a76);
  a17=(a17-a02);
  a17=(a25*a17);
  if (res[1]!=0) res[1][18]=a17;
  a58=(a26-a58);
  a27=(a27*a58);
  a59=(a28*a59);
  a27=(a27-a59);
  a27=(a25*a27);
  if (res[1]!=0) res[1][19]=a27;
  a28=(a28*a76);
  a75=(a75*a58);
  a28=(a28-a75);
  a25=(a25*a28);
  if (res[1]!=0) res[1][20]=a25;
  a68=(a24-a68);
  a25=(a78*a68);
  a82=(a74-a82);
  a28=(a42*a82);
  a25=(a25-a28);
  a25=(a41*a25);
  if (res[1]!=0) res[1][21]=a25;
  a69=(a26-a69);
  a42=(a42*a69);
  a68=(a43*a68);
  a42=(a42-a68);
  a42=(a41*a42);
  if (res[1]!=0) res[1][22]=a42;
  a43=(a43*a82);
  a78=(a78*a69);
  a43=(a43-a78);
  a41=(a41*a43);
  if (res[1]!=0) res[1][23]=a41;
  a24=(a24-a22);
  a22=(a80*a24);
  a74=(a74-a73);
  a73=(a47*a74);
  a22=(a22-a73);
  a22=(a56*a22);
  if (res[1]!=0) res[1][24]=a22;
  a26=(a26-a71);
  a47=(a47*a26);
  a24=(a62*a24);
  a47=(a47-a24);
  a47=(a56*a47);
  if (res[1]!=0) res[1][25]=a47;
  a62=(a62*a74);
  a80=(a80*a26);
  a62=(a62-a80);
  a56=(a56*a62);
  if (res[1]!=0) res[1][26]=a56;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_jacobian(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_jacobian_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_point_jacobian_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_point_jacobian_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_point_jacobian_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_point_jacobian_n_in(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_point_jacobian_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp3_point_jacobian_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_point_jacobian_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    case 2: return "link";
    case 3: return "point";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_point_jacobian_name_out(casadi_int i) {
  switch (i) {
    case 0: return "position";
    case 1: return "J";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_point_jacobian_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_point_jacobian_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_jacobian_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 4;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_jacobian_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

/* snakecg_sp3_point_jacobian_sincos: 630 CasADi instructions, printed one per line */
static void snakecg_sp3_point_jacobian_sincos(
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
  casadi_real w60, w61, w62, w63, w64, w65, w66, w67, w68, w69;
  casadi_real w70, w71, w72, w73, w74, w75, w76, w77, w78, w79;
  casadi_real w80, w81, w82;
  w0 = arg1[97];
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
  w9 = arg1[98];
  w10 = arg0[6];
  w11 = w2 * w10;
  w12 = w11 * w6;
  w13 = arg0[3];
  w14 = w13 + w13;
  w15 = w14 * w3;
  w12 = w12 + w15;
  w16 = w9 * w12;
  w8 = w8 + w16;
  w16 = arg1[99];
  w10 = w10 + w10;
  w17 = w10 * w3;
  w14 = w14 * w6;
  w17 = w17 + w14;
  w18 = w16 * w17;
  w8 = w8 + w18;
  w18 = arg4[0];
  w19 = w8 * w18;
  w20 = arg1[100];
  w21 = w20 * w5;
  w22 = arg1[101];
  w23 = w22 * w12;
  w21 = w21 + w23;
  w23 = arg1[102];
  w24 = w23 * w17;
  w21 = w21 + w24;
  w24 = arg5[0];
  w25 = w21 * w24;
  w19 = w19 + w25;
  w25 = arg2[1];
  w26 = w19 * w25;
  w27 = arg1[103];
  w28 = w27 * w5;
  w29 = arg1[104];
  w30 = w29 * w12;
  w28 = w28 + w30;
  w30 = arg1[105];
  w31 = w30 * w17;
  w28 = w28 + w31;
  w31 = arg1[108];
  w32 = w28 * w31;
  w33 = arg1[106];
  w34 = w33 * w19;
  w32 = w32 + w34;
  w34 = arg1[107];
  w21 = w21 * w18;
  w8 = w8 * w24;
  w21 = w21 - w8;
  w8 = w34 * w21;
  w32 = w32 + w8;
  w8 = arg4[1];
  w35 = w32 * w8;
  w36 = arg1[111];
  w37 = w28 * w36;
  w38 = arg1[109];
  w39 = w38 * w19;
  w37 = w37 + w39;
  w39 = arg1[110];
  w40 = w39 * w21;
  w37 = w37 + w40;
  w40 = arg5[1];
  w41 = w37 * w40;
  w35 = w35 + w41;
  w41 = arg2[2];
  w42 = w35 * w41;
  w26 = w26 + w42;
  w42 = arg1[114];
  w43 = w28 * w42;
  w44 = arg1[112];
  w45 = w44 * w19;
  w43 = w43 + w45;
  w45 = arg1[113];
  w46 = w45 * w21;
  w43 = w43 + w46;
  w46 = arg1[117];
  w47 = w43 * w46;
  w48 = arg1[115];
  w49 = w48 * w35;
  w47 = w47 + w49;
  w49 = arg1[116];
  w37 = w37 * w8;
  w32 = w32 * w40;
  w37 = w37 - w32;
  w32 = w49 * w37;
  w47 = w47 + w32;
  w32 = arg4[2];
  w50 = w47 * w32;
  w51 = arg1[120];
  w52 = w43 * w51;
  w53 = arg1[118];
  w54 = w53 * w35;
  w52 = w52 + w54;
  w54 = arg1[119];
  w55 = w54 * w37;
  w52 = w52 + w55;
  w55 = arg5[2];
  w56 = w52 * w55;
  w50 = w50 + w56;
  w56 = arg2[3];
  w50 = w50 * w56;
  w26 = w26 + w50;
  w50 = arg2[0];
  w57 = w5 * w50;
  w26 = w26 + w57;
  w57 = arg1[70];
  w57 = w57 * w25;
  w57 = w50 + w57;
  w58 = arg1[79];
  w58 = w58 * w41;
  w57 = w57 + w58;
  w58 = arg1[88];
  w58 = w58 * w56;
  w57 = w57 + w58;
  w58 = arg3[0];
  w57 = w57 * w58;
  w59 = arg1[71];
  w59 = w59 * w25;
  w60 = arg1[80];
  w60 = w60 * w41;
  w59 = w59 + w60;
  w60 = arg1[89];
  w60 = w60 * w56;
  w59 = w59 + w60;
  w60 = arg3[1];
  w59 = w59 * w60;
  w57 = w57 + w59;
  w59 = arg1[72];
  w59 = w59 * w25;
  w61 = arg1[81];
  w61 = w61 * w41;
  w59 = w59 + w61;
  w61 = arg1[90];
  w61 = w61 * w56;
  w59 = w59 + w61;
  w61 = arg3[2];
  w59 = w59 * w61;
  w57 = w57 + w59;
  w26 = w26 * w57;
  w59 = w21 * w25;
  w62 = w37 * w41;
  w59 = w59 + w62;
  w52 = w52 * w32;
  w47 = w47 * w55;
  w52 = w52 - w47;
  w52 = w52 * w56;
  w59 = w59 + w52;
  w52 = w12 * w50;
  w59 = w59 + w52;
  w52 = arg1[73];
  w52 = w52 * w25;
  w47 = arg1[82];
  w47 = w47 * w41;
  w52 = w52 + w47;
  w47 = arg1[91];
  w47 = w47 * w56;
  w52 = w52 + w47;
  w52 = w52 * w58;
  w47 = arg1[74];
  w47 = w47 * w25;
  w47 = w50 + w47;
  w62 = arg1[83];
  w62 = w62 * w41;
  w47 = w47 + w62;
  w62 = arg1[92];
  w62 = w62 * w56;
  w47 = w47 + w62;
  w47 = w47 * w60;
  w52 = w52 + w47;
  w47 = arg1[75];
  w47 = w47 * w25;
  w62 = arg1[84];
  w62 = w62 * w41;
  w47 = w47 + w62;
  w62 = arg1[93];
  w62 = w62 * w56;
  w47 = w47 + w62;
  w47 = w47 * w61;
  w52 = w52 + w47;
  w59 = w59 * w52;
  w26 = w26 + w59;
  w59 = w28 * w25;
  w47 = w43 * w41;
  w59 = w59 + w47;
  w47 = arg1[123];
  w62 = w43 * w47;
  w63 = arg1[121];
  w64 = w63 * w35;
  w62 = w62 + w64;
  w64 = arg1[122];
  w65 = w64 * w37;
  w62 = w62 + w65;
  w65 = w62 * w56;
  w59 = w59 + w65;
  w65 = w17 * w50;
  w59 = w59 + w65;
  w65 = arg1[76];
  w65 = w65 * w25;
  w66 = arg1[85];
  w66 = w66 * w41;
  w65 = w65 + w66;
  w66 = arg1[94];
  w66 = w66 * w56;
  w65 = w65 + w66;
  w65 = w65 * w58;
  w58 = arg1[77];
  w58 = w58 * w25;
  w66 = arg1[86];
  w66 = w66 * w41;
  w58 = w58 + w66;
  w66 = arg1[95];
  w66 = w66 * w56;
  w58 = w58 + w66;
  w58 = w58 * w60;
  w65 = w65 + w58;
  w58 = arg1[78];
  w58 = w58 * w25;
  w58 = w50 + w58;
  w60 = arg1[87];
  w60 = w60 * w41;
  w58 = w58 + w60;
  w60 = arg1[96];
  w60 = w60 * w56;
  w58 = w58 + w60;
  w58 = w58 * w61;
  w65 = w65 + w58;
  w59 = w59 * w65;
  w26 = w26 + w59;
  w59 = arg1[124];
  w58 = w5 * w59;
  w61 = arg1[125];
  w60 = w12 * w61;
  w58 = w58 + w60;
  w60 = arg1[126];
  w66 = w17 * w60;
  w58 = w58 + w66;
  w66 = arg0[0];
  w58 = w58 + w66;
  w67 = w58 * w25;
  w68 = arg1[129];
  w69 = w28 * w68;
  w70 = arg1[127];
  w19 = w19 * w70;
  w69 = w69 + w19;
  w19 = arg1[128];
  w21 = w21 * w19;
  w69 = w69 + w21;
  w69 = w69 + w58;
  w21 = w69 * w41;
  w67 = w67 + w21;
  w21 = arg1[132];
  w71 = w43 * w21;
  w72 = arg1[130];
  w35 = w35 * w72;
  w71 = w71 + w35;
  w35 = arg1[131];
  w37 = w37 * w35;
  w71 = w71 + w37;
  w71 = w71 + w69;
  w37 = w71 * w56;
  w67 = w67 + w37;
  w37 = w50 * w66;
  w67 = w67 + w37;
  w26 = w26 + w67;
  res0[0] = w26;
  w67 = w10 * w6;
  w67 = w67 + w15;
  w15 = w0 * w67;
  w37 = w13 * w13;
  w2 = w2 * w37;
  w1 = w1 + w2;
  w7 = w1 + w7;
  w2 = w9 * w7;
  w15 = w15 + w2;
  w2 = w11 * w13;
  w37 = w3 + w3;
  w37 = w37 * w6;
  w2 = w2 + w37;
  w6 = w16 * w2;
  w15 = w15 + w6;
  w6 = w15 * w18;
  w73 = w20 * w67;
  w74 = w22 * w7;
  w73 = w73 + w74;
  w74 = w23 * w2;
  w73 = w73 + w74;
  w74 = w73 * w24;
  w6 = w6 + w74;
  w74 = w6 * w25;
  w75 = w27 * w67;
  w76 = w29 * w7;
  w75 = w75 + w76;
  w76 = w30 * w2;
  w75 = w75 + w76;
  w76 = w75 * w31;
  w77 = w33 * w6;
  w76 = w76 + w77;
  w73 = w73 * w18;
  w15 = w15 * w24;
  w73 = w73 - w15;
  w15 = w34 * w73;
  w76 = w76 + w15;
  w15 = w76 * w8;
  w77 = w75 * w36;
  w78 = w38 * w6;
  w77 = w77 + w78;
  w78 = w39 * w73;
  w77 = w77 + w78;
  w78 = w77 * w40;
  w15 = w15 + w78;
  w78 = w15 * w41;
  w74 = w74 + w78;
  w78 = w75 * w42;
  w79 = w44 * w6;
  w78 = w78 + w79;
  w79 = w45 * w73;
  w78 = w78 + w79;
  w79 = w78 * w46;
  w80 = w48 * w15;
  w79 = w79 + w80;
  w77 = w77 * w8;
  w76 = w76 * w40;
  w77 = w77 - w76;
  w76 = w49 * w77;
  w79 = w79 + w76;
  w76 = w79 * w32;
  w80 = w78 * w51;
  w81 = w53 * w15;
  w80 = w80 + w81;
  w81 = w54 * w77;
  w80 = w80 + w81;
  w81 = w80 * w55;
  w76 = w76 + w81;
  w76 = w76 * w56;
  w74 = w74 + w76;
  w76 = w67 * w50;
  w74 = w74 + w76;
  w74 = w74 * w57;
  w76 = w73 * w25;
  w81 = w77 * w41;
  w76 = w76 + w81;
  w80 = w80 * w32;
  w79 = w79 * w55;
  w80 = w80 - w79;
  w80 = w80 * w56;
  w76 = w76 + w80;
  w80 = w7 * w50;
  w76 = w76 + w80;
  w76 = w76 * w52;
  w74 = w74 + w76;
  w76 = w75 * w25;
  w80 = w78 * w41;
  w76 = w76 + w80;
  w80 = w78 * w47;
  w79 = w63 * w15;
  w80 = w80 + w79;
  w79 = w64 * w77;
  w80 = w80 + w79;
  w79 = w80 * w56;
  w76 = w76 + w79;
  w79 = w2 * w50;
  w76 = w76 + w79;
  w76 = w76 * w65;
  w74 = w74 + w76;
  w76 = w67 * w59;
  w79 = w7 * w61;
  w76 = w76 + w79;
  w79 = w2 * w60;
  w76 = w76 + w79;
  w79 = arg0[1];
  w76 = w76 + w79;
  w81 = w76 * w25;
  w82 = w75 * w68;
  w6 = w6 * w70;
  w82 = w82 + w6;
  w73 = w73 * w19;
  w82 = w82 + w73;
  w82 = w82 + w76;
  w73 = w82 * w41;
  w81 = w81 + w73;
  w73 = w78 * w21;
  w15 = w15 * w72;
  w73 = w73 + w15;
  w77 = w77 * w35;
  w73 = w73 + w77;
  w73 = w73 + w82;
  w77 = w73 * w56;
  w81 = w81 + w77;
  w77 = w50 * w79;
  w81 = w81 + w77;
  w74 = w74 + w81;
  res0[1] = w74;
  w11 = w11 * w3;
  w11 = w11 + w14;
  w0 = w0 * w11;
  w10 = w10 * w13;
  w10 = w10 + w37;
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
  w39 = w34 * w41;
  w23 = w23 + w39;
  w42 = w27 * w42;
  w44 = w44 * w16;
  w42 = w42 + w44;
  w45 = w45 * w20;
  w42 = w42 + w45;
  w46 = w42 * w46;
  w48 = w48 * w34;
  w46 = w46 + w48;
  w36 = w36 * w8;
  w31 = w31 * w40;
  w36 = w36 - w31;
  w49 = w49 * w36;
  w46 = w46 + w49;
  w49 = w46 * w32;
  w51 = w42 * w51;
  w53 = w53 * w34;
  w51 = w51 + w53;
  w54 = w54 * w36;
  w51 = w51 + w54;
  w54 = w51 * w55;
  w49 = w49 + w54;
  w49 = w49 * w56;
  w23 = w23 + w49;
  w49 = w11 * w50;
  w23 = w23 + w49;
  w23 = w23 * w57;
  w57 = w20 * w25;
  w49 = w36 * w41;
  w57 = w57 + w49;
  w51 = w51 * w32;
  w46 = w46 * w55;
  w51 = w51 - w46;
  w51 = w51 * w56;
  w57 = w57 + w51;
  w51 = w10 * w50;
  w57 = w57 + w51;
  w57 = w57 * w52;
  w23 = w23 + w57;
  w57 = w27 * w25;
  w52 = w42 * w41;
  w57 = w57 + w52;
  w47 = w42 * w47;
  w63 = w63 * w34;
  w47 = w47 + w63;
  w64 = w64 * w36;
  w47 = w47 + w64;
  w64 = w47 * w56;
  w57 = w57 + w64;
  w64 = w1 * w50;
  w57 = w57 + w64;
  w57 = w57 * w65;
  w23 = w23 + w57;
  w59 = w11 * w59;
  w61 = w10 * w61;
  w59 = w59 + w61;
  w60 = w1 * w60;
  w59 = w59 + w60;
  w60 = arg0[2];
  w59 = w59 + w60;
  w61 = w59 * w25;
  w68 = w27 * w68;
  w16 = w16 * w70;
  w68 = w68 + w16;
  w20 = w20 * w19;
  w68 = w68 + w20;
  w68 = w68 + w59;
  w20 = w68 * w41;
  w61 = w61 + w20;
  w21 = w42 * w21;
  w34 = w34 * w72;
  w21 = w21 + w34;
  w36 = w36 * w35;
  w21 = w21 + w36;
  w21 = w21 + w68;
  w36 = w21 * w56;
  w61 = w61 + w36;
  w50 = w50 * w60;
  w61 = w61 + w50;
  w23 = w23 + w61;
  res0[2] = w23;
  res1[0] = w5;
  res1[1] = w67;
  res1[2] = w11;
  res1[3] = w12;
  res1[4] = w7;
  res1[5] = w10;
  res1[6] = w17;
  res1[7] = w2;
  res1[8] = w1;
  w60 = w23 - w60;
  w61 = w67 * w60;
  w79 = w74 - w79;
  w50 = w11 * w79;
  w61 = w61 - w50;
  res1[9] = w61;
  w66 = w26 - w66;
  w11 = w11 * w66;
  w61 = w5 * w60;
  w11 = w11 - w61;
  res1[10] = w11;
  w5 = w5 * w79;
  w67 = w67 * w66;
  w5 = w5 - w67;
  res1[11] = w5;
  w5 = w7 * w60;
  w67 = w10 * w79;
  w5 = w5 - w67;
  res1[12] = w5;
  w10 = w10 * w66;
  w5 = w12 * w60;
  w10 = w10 - w5;
  res1[13] = w10;
  w12 = w12 * w79;
  w7 = w7 * w66;
  w12 = w12 - w7;
  res1[14] = w12;
  w12 = w2 * w60;
  w7 = w1 * w79;
  w12 = w12 - w7;
  res1[15] = w12;
  w1 = w1 * w66;
  w60 = w17 * w60;
  w1 = w1 - w60;
  res1[16] = w1;
  w17 = w17 * w79;
  w2 = w2 * w66;
  w17 = w17 - w2;
  res1[17] = w17;
  w41 = w41 + w56;
  w25 = w41 + w25;
  w59 = w23 - w59;
  w17 = w75 * w59;
  w76 = w74 - w76;
  w2 = w27 * w76;
  w17 = w17 - w2;
  w17 = w25 * w17;
  res1[18] = w17;
  w58 = w26 - w58;
  w27 = w27 * w58;
  w59 = w28 * w59;
  w27 = w27 - w59;
  w27 = w25 * w27;
  res1[19] = w27;
  w28 = w28 * w76;
  w75 = w75 * w58;
  w28 = w28 - w75;
  w25 = w25 * w28;
  res1[20] = w25;
  w68 = w23 - w68;
  w25 = w78 * w68;
  w82 = w74 - w82;
  w28 = w42 * w82;
  w25 = w25 - w28;
  w25 = w41 * w25;
  res1[21] = w25;
  w69 = w26 - w69;
  w42 = w42 * w69;
  w68 = w43 * w68;
  w42 = w42 - w68;
  w42 = w41 * w42;
  res1[22] = w42;
  w43 = w43 * w82;
  w78 = w78 * w69;
  w43 = w43 - w78;
  w41 = w41 * w43;
  res1[23] = w41;
  w23 = w23 - w21;
  w21 = w80 * w23;
  w74 = w74 - w73;
  w73 = w47 * w74;
  w21 = w21 - w73;
  w21 = w56 * w21;
  res1[24] = w21;
  w26 = w26 - w71;
  w47 = w47 * w26;
  w23 = w62 * w23;
  w47 = w47 - w23;
  w47 = w56 * w47;
  res1[25] = w47;
  w62 = w62 * w74;
  w80 = w80 * w26;
  w62 = w62 - w80;
  w56 = w56 * w62;
  res1[26] = w56;
}


CASADI_SYMBOL_EXPORT int snakecg_sp3_batch_point_jacobian(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[4];
  casadi_real* r[2];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 84);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 4; ++k) a[k] = 0;
  for (k = 0; k < 2; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && res[0] && res[1]) {
    /* cos and sin of q[7..9] of 16 samples at a time, then snakecg_sp3_point_jacobian_sincos
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
        snakecg_sp3_point_jacobian_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], ca + i * na, sa + i * na, res[0] + (i0 + i) * 3, res[1] + (i0 + i) * 27);
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
      r[1] = res[1] + i * 27;
      if (snakecg_sp3_point_jacobian(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
