/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for point_bias_acceleration() of
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
  #define CASADI_PREFIX(ID) snakecg_sp3_point_bias_acceleration_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp3_point_bias_acceleration_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp3_point_bias_acceleration_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp3_point_bias_acceleration_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {10, 1, 1};
static const casadi_int casadi_s1[3] = {9, 1, 1};
static const casadi_int casadi_s2[3] = {169, 1, 1};
static const casadi_int casadi_s3[3] = {4, 1, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};

/* snakecg_sp3_point_bias_acceleration:(q[10],v[9],K[169],link[4],point[3])->(bias[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85;
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
  a28=arg[2]? arg[2][124] : 0;
  a29=(a03*a28);
  a30=arg[2]? arg[2][125] : 0;
  a31=(a14*a30);
  a29=(a29+a31);
  a31=arg[2]? arg[2][126] : 0;
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
  a06=arg[2]? arg[2][103] : 0;
  a15=(a06*a10);
  a07=arg[2]? arg[2][104] : 0;
  a02=(a07*a00);
  a15=(a15+a02);
  a02=arg[2]? arg[2][105] : 0;
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
  a32=arg[2]? arg[2][129] : 0;
  a33=(a11*a32);
  a34=arg[2]? arg[2][97] : 0;
  a35=(a34*a19);
  a36=arg[2]? arg[2][98] : 0;
  a37=(a36*a04);
  a35=(a35+a37);
  a37=arg[2]? arg[2][99] : 0;
  a38=(a37*a12);
  a35=(a35+a38);
  a38=arg[0]? arg[0][7] : 0;
  a39=cos(a38);
  a40=(a35*a39);
  a41=arg[2]? arg[2][100] : 0;
  a42=(a41*a19);
  a43=arg[2]? arg[2][101] : 0;
  a44=(a43*a04);
  a42=(a42+a44);
  a44=arg[2]? arg[2][102] : 0;
  a45=(a44*a12);
  a42=(a42+a45);
  a38=sin(a38);
  a45=(a42*a38);
  a40=(a40+a45);
  a45=arg[2]? arg[2][127] : 0;
  a46=(a40*a45);
  a33=(a33+a46);
  a42=(a42*a39);
  a35=(a35*a38);
  a42=(a42-a35);
  a35=arg[2]? arg[2][128] : 0;
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
  a45=(a23*a39);
  a27=(a27+a45);
  a45=arg[1]? arg[1][7] : 0;
  a44=arg[2]? arg[2][114] : 0;
  a43=(a15*a44);
  a36=arg[2]? arg[2][112] : 0;
  a50=(a36*a37);
  a43=(a43+a50);
  a50=arg[2]? arg[2][113] : 0;
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
  a53=arg[2]? arg[2][132] : 0;
  a54=(a52*a53);
  a55=arg[2]? arg[2][108] : 0;
  a56=(a11*a55);
  a57=arg[2]? arg[2][106] : 0;
  a58=(a57*a40);
  a56=(a56+a58);
  a58=arg[2]? arg[2][107] : 0;
  a59=(a58*a42);
  a56=(a56+a59);
  a59=arg[0]? arg[0][8] : 0;
  a60=cos(a59);
  a61=(a56*a60);
  a62=arg[2]? arg[2][111] : 0;
  a63=(a11*a62);
  a64=arg[2]? arg[2][109] : 0;
  a65=(a64*a40);
  a63=(a63+a65);
  a65=arg[2]? arg[2][110] : 0;
  a66=(a65*a42);
  a63=(a63+a66);
  a59=sin(a59);
  a66=(a63*a59);
  a61=(a61+a66);
  a66=arg[2]? arg[2][130] : 0;
  a67=(a61*a66);
  a54=(a54+a67);
  a63=(a63*a60);
  a56=(a56*a59);
  a63=(a63-a56);
  a56=arg[2]? arg[2][131] : 0;
  a67=(a63*a56);
  a54=(a54+a67);
  a67=(a51*a54);
  a23=(a23+a67);
  a44=(a06*a44);
  a36=(a36*a47);
  a44=(a44+a36);
  a50=(a50*a48);
  a44=(a44+a50);
  a50=(a44*a45);
  a50=(a02+a50);
  a36=(a44*a53);
  a67=(a06*a55);
  a68=(a57*a47);
  a67=(a67+a68);
  a68=(a58*a48);
  a67=(a67+a68);
  a68=(a67*a60);
  a69=(a06*a62);
  a70=(a64*a47);
  a69=(a69+a70);
  a70=(a65*a48);
  a69=(a69+a70);
  a70=(a69*a59);
  a68=(a68+a70);
  a70=(a68*a66);
  a36=(a36+a70);
  a69=(a69*a60);
  a67=(a67*a59);
  a69=(a69-a67);
  a67=(a69*a56);
  a36=(a36+a67);
  a67=(a43*a45);
  a67=(a46+a67);
  a70=(a36*a67);
  a53=(a43*a53);
  a55=(a15*a55);
  a57=(a57*a37);
  a55=(a55+a57);
  a58=(a58*a41);
  a55=(a55+a58);
  a58=(a55*a60);
  a62=(a15*a62);
  a64=(a64*a37);
  a62=(a62+a64);
  a65=(a65*a41);
  a62=(a62+a65);
  a65=(a62*a59);
  a58=(a58+a65);
  a66=(a58*a66);
  a53=(a53+a66);
  a62=(a62*a60);
  a55=(a55*a59);
  a62=(a62-a55);
  a56=(a62*a56);
  a53=(a53+a56);
  a56=(a53*a50);
  a70=(a70-a56);
  a56=(a50*a70);
  a23=(a23+a56);
  a56=(a44*a46);
  a55=(a43*a02);
  a56=(a56-a55);
  a56=(a45*a56);
  a56=(a35+a56);
  a55=(a56*a36);
  a23=(a23-a55);
  a55=(a52*a45);
  a55=(a34+a55);
  a59=(a53*a55);
  a60=(a54*a67);
  a59=(a59-a60);
  a60=(a55*a59);
  a23=(a23-a60);
  a60=arg[3]? arg[3][3] : 0;
  a23=(a23*a60);
  a27=(a27+a23);
  a23=(a13*a31);
  a66=(a51*a39);
  a23=(a23+a66);
  a66=arg[1]? arg[1][8] : 0;
  a65=arg[2]? arg[2][123] : 0;
  a64=(a43*a65);
  a57=arg[2]? arg[2][121] : 0;
  a71=(a57*a58);
  a64=(a64+a71);
  a71=arg[2]? arg[2][122] : 0;
  a72=(a71*a62);
  a64=(a64+a72);
  a72=(a64*a55);
  a73=(a52*a65);
  a74=(a57*a61);
  a73=(a73+a74);
  a74=(a71*a63);
  a73=(a73+a74);
  a74=(a73*a67);
  a72=(a72-a74);
  a72=(a66*a72);
  a72=(a51+a72);
  a72=(a72*a60);
  a23=(a23+a72);
  a40=(a40*a31);
  a72=(a61*a39);
  a40=(a40+a72);
  a72=arg[2]? arg[2][117] : 0;
  a74=(a52*a72);
  a75=arg[2]? arg[2][115] : 0;
  a76=(a75*a61);
  a74=(a74+a76);
  a76=arg[2]? arg[2][116] : 0;
  a77=(a76*a63);
  a74=(a74+a77);
  a77=arg[0]? arg[0][9] : 0;
  a78=cos(a77);
  a79=(a74*a78);
  a80=arg[2]? arg[2][120] : 0;
  a81=(a52*a80);
  a82=arg[2]? arg[2][118] : 0;
  a61=(a82*a61);
  a81=(a81+a61);
  a61=arg[2]? arg[2][119] : 0;
  a83=(a61*a63);
  a81=(a81+a83);
  a77=sin(a77);
  a83=(a81*a77);
  a79=(a79+a83);
  a79=(a79*a60);
  a40=(a40+a79);
  a19=(a19*a26);
  a40=(a40+a19);
  a19=arg[2]? arg[2][70] : 0;
  a19=(a19*a31);
  a19=(a26+a19);
  a79=arg[2]? arg[2][79] : 0;
  a79=(a79*a39);
  a19=(a19+a79);
  a79=arg[2]? arg[2][88] : 0;
  a79=(a79*a60);
  a19=(a19+a79);
  a79=arg[4]? arg[4][0] : 0;
  a19=(a19*a79);
  a83=arg[2]? arg[2][71] : 0;
  a83=(a83*a31);
  a84=arg[2]? arg[2][80] : 0;
  a84=(a84*a39);
  a83=(a83+a84);
  a84=arg[2]? arg[2][89] : 0;
  a84=(a84*a60);
  a83=(a83+a84);
  a84=arg[4]? arg[4][1] : 0;
  a83=(a83*a84);
  a19=(a19+a83);
  a83=arg[2]? arg[2][72] : 0;
  a83=(a83*a31);
  a85=arg[2]? arg[2][81] : 0;
  a85=(a85*a39);
  a83=(a83+a85);
  a85=arg[2]? arg[2][90] : 0;
  a85=(a85*a60);
  a83=(a83+a85);
  a85=arg[4]? arg[4][2] : 0;
  a83=(a83*a85);
  a19=(a19+a83);
  a40=(a40*a19);
  a42=(a42*a31);
  a63=(a63*a39);
  a42=(a42+a63);
  a81=(a81*a78);
  a74=(a74*a77);
  a81=(a81-a74);
  a81=(a81*a60);
  a42=(a42+a81);
  a04=(a04*a26);
  a42=(a42+a04);
  a04=arg[2]? arg[2][73] : 0;
  a04=(a04*a31);
  a81=arg[2]? arg[2][82] : 0;
  a81=(a81*a39);
  a04=(a04+a81);
  a81=arg[2]? arg[2][91] : 0;
  a81=(a81*a60);
  a04=(a04+a81);
  a04=(a04*a79);
  a81=arg[2]? arg[2][74] : 0;
  a81=(a81*a31);
  a81=(a26+a81);
  a74=arg[2]? arg[2][83] : 0;
  a74=(a74*a39);
  a81=(a81+a74);
  a74=arg[2]? arg[2][92] : 0;
  a74=(a74*a60);
  a81=(a81+a74);
  a81=(a81*a84);
  a04=(a04+a81);
  a81=arg[2]? arg[2][75] : 0;
  a81=(a81*a31);
  a74=arg[2]? arg[2][84] : 0;
  a74=(a74*a39);
  a81=(a81+a74);
  a74=arg[2]? arg[2][93] : 0;
  a74=(a74*a60);
  a81=(a81+a74);
  a81=(a81*a85);
  a04=(a04+a81);
  a42=(a42*a04);
  a40=(a40+a42);
  a42=(a11*a31);
  a81=(a52*a39);
  a42=(a42+a81);
  a81=(a73*a60);
  a42=(a42+a81);
  a12=(a12*a26);
  a42=(a42+a12);
  a12=arg[2]? arg[2][76] : 0;
  a12=(a12*a31);
  a81=arg[2]? arg[2][85] : 0;
  a81=(a81*a39);
  a12=(a12+a81);
  a81=arg[2]? arg[2][94] : 0;
  a81=(a81*a60);
  a12=(a12+a81);
  a12=(a12*a79);
  a79=arg[2]? arg[2][77] : 0;
  a79=(a79*a31);
  a81=arg[2]? arg[2][86] : 0;
  a81=(a81*a39);
  a79=(a79+a81);
  a81=arg[2]? arg[2][95] : 0;
  a81=(a81*a60);
  a79=(a79+a81);
  a79=(a79*a84);
  a12=(a12+a79);
  a79=arg[2]? arg[2][78] : 0;
  a79=(a79*a31);
  a79=(a26+a79);
  a84=arg[2]? arg[2][87] : 0;
  a84=(a84*a39);
  a79=(a79+a84);
  a84=arg[2]? arg[2][96] : 0;
  a84=(a84*a60);
  a79=(a79+a84);
  a79=(a79*a85);
  a12=(a12+a79);
  a42=(a42*a12);
  a40=(a40+a42);
  a42=(a23*a40);
  a27=(a27+a42);
  a42=(a09*a26);
  a79=(a02*a31);
  a42=(a42+a79);
  a79=(a50*a39);
  a42=(a42+a79);
  a65=(a44*a65);
  a57=(a57*a68);
  a65=(a65+a57);
  a71=(a71*a69);
  a65=(a65+a71);
  a71=(a65*a66);
  a71=(a50+a71);
  a71=(a71*a60);
  a42=(a42+a71);
  a47=(a47*a31);
  a71=(a68*a39);
  a47=(a47+a71);
  a71=(a44*a72);
  a57=(a75*a68);
  a71=(a71+a57);
  a57=(a76*a69);
  a71=(a71+a57);
  a57=(a71*a78);
  a79=(a44*a80);
  a68=(a82*a68);
  a79=(a79+a68);
  a68=(a61*a69);
  a79=(a79+a68);
  a68=(a79*a77);
  a57=(a57+a68);
  a57=(a57*a60);
  a47=(a47+a57);
  a03=(a03*a26);
  a47=(a47+a03);
  a47=(a47*a19);
  a48=(a48*a31);
  a69=(a69*a39);
  a48=(a48+a69);
  a79=(a79*a78);
  a71=(a71*a77);
  a79=(a79-a71);
  a79=(a79*a60);
  a48=(a48+a79);
  a14=(a14*a26);
  a48=(a48+a14);
  a48=(a48*a04);
  a47=(a47+a48);
  a48=(a06*a31);
  a14=(a44*a39);
  a48=(a48+a14);
  a14=(a65*a60);
  a48=(a48+a14);
  a16=(a16*a26);
  a48=(a48+a16);
  a48=(a48*a12);
  a47=(a47+a48);
  a48=(a08*a26);
  a16=(a46*a31);
  a48=(a48+a16);
  a16=(a67*a39);
  a48=(a48+a16);
  a16=(a64*a66);
  a16=(a67+a16);
  a16=(a16*a60);
  a48=(a48+a16);
  a16=(a47*a48);
  a37=(a37*a31);
  a14=(a58*a39);
  a37=(a37+a14);
  a72=(a43*a72);
  a75=(a75*a58);
  a72=(a72+a75);
  a76=(a76*a62);
  a72=(a72+a76);
  a76=(a72*a78);
  a80=(a43*a80);
  a82=(a82*a58);
  a80=(a80+a82);
  a61=(a61*a62);
  a80=(a80+a61);
  a61=(a80*a77);
  a76=(a76+a61);
  a76=(a76*a60);
  a37=(a37+a76);
  a76=(a10*a26);
  a37=(a37+a76);
  a37=(a37*a19);
  a41=(a41*a31);
  a62=(a62*a39);
  a41=(a41+a62);
  a80=(a80*a78);
  a72=(a72*a77);
  a80=(a80-a72);
  a80=(a80*a60);
  a41=(a41+a80);
  a80=(a00*a26);
  a41=(a41+a80);
  a41=(a41*a04);
  a37=(a37+a41);
  a15=(a15*a31);
  a43=(a43*a39);
  a15=(a15+a43);
  a43=(a64*a60);
  a15=(a15+a43);
  a43=(a01*a26);
  a15=(a15+a43);
  a15=(a15*a12);
  a37=(a37+a15);
  a15=(a37*a42);
  a16=(a16-a15);
  a15=(a42*a16);
  a27=(a27+a15);
  a15=(a35*a31);
  a12=(a56*a39);
  a15=(a15+a12);
  a12=(a65*a67);
  a64=(a64*a50);
  a12=(a12-a64);
  a12=(a66*a12);
  a12=(a56+a12);
  a12=(a12*a60);
  a15=(a15+a12);
  a12=(a15*a47);
  a27=(a27-a12);
  a12=(a24*a26);
  a64=(a34*a31);
  a12=(a12+a64);
  a64=(a55*a39);
  a12=(a12+a64);
  a64=(a73*a66);
  a64=(a55+a64);
  a64=(a64*a60);
  a12=(a12+a64);
  a64=(a37*a12);
  a43=(a40*a48);
  a64=(a64-a43);
  a43=(a12*a64);
  a27=(a27-a43);
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
  a49=(a01*a39);
  a21=(a21+a49);
  a56=(a56*a53);
  a01=(a01+a56);
  a56=(a54*a50);
  a49=(a36*a55);
  a56=(a56-a49);
  a49=(a55*a56);
  a01=(a01+a49);
  a52=(a52*a02);
  a44=(a44*a34);
  a52=(a52-a44);
  a45=(a45*a52);
  a45=(a30+a45);
  a54=(a45*a54);
  a01=(a01-a54);
  a70=(a67*a70);
  a01=(a01-a70);
  a01=(a01*a60);
  a21=(a21+a01);
  a15=(a15*a37);
  a21=(a21+a15);
  a15=(a40*a42);
  a01=(a47*a12);
  a15=(a15-a01);
  a12=(a12*a15);
  a21=(a21+a12);
  a12=(a30*a31);
  a01=(a45*a39);
  a12=(a12+a01);
  a73=(a73*a50);
  a65=(a65*a55);
  a73=(a73-a65);
  a66=(a66*a73);
  a66=(a45+a66);
  a66=(a66*a60);
  a12=(a12+a66);
  a40=(a12*a40);
  a21=(a21-a40);
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
  a39=(a25*a39);
  a26=(a26+a39);
  a45=(a45*a36);
  a25=(a25+a45);
  a67=(a67*a59);
  a25=(a25+a67);
  a51=(a51*a53);
  a25=(a25-a51);
  a50=(a50*a56);
  a25=(a25-a50);
  a25=(a25*a60);
  a26=(a26+a25);
  a12=(a12*a47);
  a26=(a26+a12);
  a48=(a48*a64);
  a26=(a26+a48);
  a23=(a23*a37);
  a26=(a26-a23);
  a42=(a42*a15);
  a26=(a26-a42);
  if (res[0]!=0) res[0][2]=a26;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_bias_acceleration(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_bias_acceleration_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_point_bias_acceleration_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_point_bias_acceleration_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp3_point_bias_acceleration_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_point_bias_acceleration_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp3_point_bias_acceleration_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp3_point_bias_acceleration_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_point_bias_acceleration_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "link";
    case 4: return "point";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp3_point_bias_acceleration_name_out(casadi_int i) {
  switch (i) {
    case 0: return "bias";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_point_bias_acceleration_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp3_point_bias_acceleration_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_bias_acceleration_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp3_point_bias_acceleration_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
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

/* snakecg_sp3_point_bias_acceleration_sincos: 775 CasADi instructions, printed one per line */
static void snakecg_sp3_point_bias_acceleration_sincos(
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
  casadi_real w60, w61, w62, w63, w64, w65, w66, w67, w68, w69;
  casadi_real w70, w71, w72, w73, w74, w75, w76, w77, w78, w79;
  casadi_real w80, w81, w82, w83, w84, w85;
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
  w28 = arg2[124];
  w29 = w3 * w28;
  w30 = arg2[125];
  w31 = w14 * w30;
  w29 = w29 + w31;
  w31 = arg2[126];
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
  w6 = arg2[103];
  w15 = w6 * w10;
  w7 = arg2[104];
  w2 = w7 * w0;
  w15 = w15 + w2;
  w2 = arg2[105];
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
  w32 = arg2[129];
  w33 = w11 * w32;
  w34 = arg2[97];
  w35 = w34 * w19;
  w36 = arg2[98];
  w37 = w36 * w4;
  w35 = w35 + w37;
  w37 = arg2[99];
  w38 = w37 * w12;
  w35 = w35 + w38;
  w38 = arg5[0];
  w39 = w35 * w38;
  w40 = arg2[100];
  w41 = w40 * w19;
  w42 = arg2[101];
  w43 = w42 * w4;
  w41 = w41 + w43;
  w43 = arg2[102];
  w44 = w43 * w12;
  w41 = w41 + w44;
  w44 = arg6[0];
  w45 = w41 * w44;
  w39 = w39 + w45;
  w45 = arg2[127];
  w46 = w39 * w45;
  w33 = w33 + w46;
  w41 = w41 * w38;
  w35 = w35 * w44;
  w41 = w41 - w35;
  w35 = arg2[128];
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
  w45 = w23 * w38;
  w27 = w27 + w45;
  w45 = arg1[7];
  w43 = arg2[114];
  w42 = w15 * w43;
  w36 = arg2[112];
  w50 = w36 * w37;
  w42 = w42 + w50;
  w50 = arg2[113];
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
  w53 = arg2[132];
  w54 = w52 * w53;
  w55 = arg2[108];
  w56 = w11 * w55;
  w57 = arg2[106];
  w58 = w57 * w39;
  w56 = w56 + w58;
  w58 = arg2[107];
  w59 = w58 * w41;
  w56 = w56 + w59;
  w59 = arg5[1];
  w60 = w56 * w59;
  w61 = arg2[111];
  w62 = w11 * w61;
  w63 = arg2[109];
  w64 = w63 * w39;
  w62 = w62 + w64;
  w64 = arg2[110];
  w65 = w64 * w41;
  w62 = w62 + w65;
  w65 = arg6[1];
  w66 = w62 * w65;
  w60 = w60 + w66;
  w66 = arg2[130];
  w67 = w60 * w66;
  w54 = w54 + w67;
  w62 = w62 * w59;
  w56 = w56 * w65;
  w62 = w62 - w56;
  w56 = arg2[131];
  w67 = w62 * w56;
  w54 = w54 + w67;
  w67 = w51 * w54;
  w23 = w23 + w67;
  w43 = w6 * w43;
  w36 = w36 * w47;
  w43 = w43 + w36;
  w50 = w50 * w48;
  w43 = w43 + w50;
  w50 = w43 * w45;
  w50 = w2 + w50;
  w36 = w43 * w53;
  w67 = w6 * w55;
  w68 = w57 * w47;
  w67 = w67 + w68;
  w68 = w58 * w48;
  w67 = w67 + w68;
  w68 = w67 * w59;
  w69 = w6 * w61;
  w70 = w63 * w47;
  w69 = w69 + w70;
  w70 = w64 * w48;
  w69 = w69 + w70;
  w70 = w69 * w65;
  w68 = w68 + w70;
  w70 = w68 * w66;
  w36 = w36 + w70;
  w69 = w69 * w59;
  w67 = w67 * w65;
  w69 = w69 - w67;
  w67 = w69 * w56;
  w36 = w36 + w67;
  w67 = w42 * w45;
  w67 = w46 + w67;
  w70 = w36 * w67;
  w53 = w42 * w53;
  w55 = w15 * w55;
  w57 = w57 * w37;
  w55 = w55 + w57;
  w58 = w58 * w40;
  w55 = w55 + w58;
  w58 = w55 * w59;
  w61 = w15 * w61;
  w63 = w63 * w37;
  w61 = w61 + w63;
  w64 = w64 * w40;
  w61 = w61 + w64;
  w64 = w61 * w65;
  w58 = w58 + w64;
  w66 = w58 * w66;
  w53 = w53 + w66;
  w61 = w61 * w59;
  w55 = w55 * w65;
  w61 = w61 - w55;
  w56 = w61 * w56;
  w53 = w53 + w56;
  w56 = w53 * w50;
  w70 = w70 - w56;
  w56 = w50 * w70;
  w23 = w23 + w56;
  w56 = w43 * w46;
  w55 = w42 * w2;
  w56 = w56 - w55;
  w56 = w45 * w56;
  w56 = w35 + w56;
  w55 = w56 * w36;
  w23 = w23 - w55;
  w55 = w52 * w45;
  w55 = w34 + w55;
  w65 = w53 * w55;
  w59 = w54 * w67;
  w65 = w65 - w59;
  w59 = w55 * w65;
  w23 = w23 - w59;
  w59 = arg3[3];
  w23 = w23 * w59;
  w27 = w27 + w23;
  w23 = w13 * w31;
  w66 = w51 * w38;
  w23 = w23 + w66;
  w66 = arg1[8];
  w64 = arg2[123];
  w63 = w42 * w64;
  w57 = arg2[121];
  w71 = w57 * w58;
  w63 = w63 + w71;
  w71 = arg2[122];
  w72 = w71 * w61;
  w63 = w63 + w72;
  w72 = w63 * w55;
  w73 = w52 * w64;
  w74 = w57 * w60;
  w73 = w73 + w74;
  w74 = w71 * w62;
  w73 = w73 + w74;
  w74 = w73 * w67;
  w72 = w72 - w74;
  w72 = w66 * w72;
  w72 = w51 + w72;
  w72 = w72 * w59;
  w23 = w23 + w72;
  w39 = w39 * w31;
  w72 = w60 * w38;
  w39 = w39 + w72;
  w72 = arg2[117];
  w74 = w52 * w72;
  w75 = arg2[115];
  w76 = w75 * w60;
  w74 = w74 + w76;
  w76 = arg2[116];
  w77 = w76 * w62;
  w74 = w74 + w77;
  w77 = arg5[2];
  w78 = w74 * w77;
  w79 = arg2[120];
  w80 = w52 * w79;
  w81 = arg2[118];
  w60 = w81 * w60;
  w80 = w80 + w60;
  w60 = arg2[119];
  w82 = w60 * w62;
  w80 = w80 + w82;
  w82 = arg6[2];
  w83 = w80 * w82;
  w78 = w78 + w83;
  w78 = w78 * w59;
  w39 = w39 + w78;
  w19 = w19 * w26;
  w39 = w39 + w19;
  w19 = arg2[70];
  w19 = w19 * w31;
  w19 = w26 + w19;
  w78 = arg2[79];
  w78 = w78 * w38;
  w19 = w19 + w78;
  w78 = arg2[88];
  w78 = w78 * w59;
  w19 = w19 + w78;
  w78 = arg4[0];
  w19 = w19 * w78;
  w83 = arg2[71];
  w83 = w83 * w31;
  w84 = arg2[80];
  w84 = w84 * w38;
  w83 = w83 + w84;
  w84 = arg2[89];
  w84 = w84 * w59;
  w83 = w83 + w84;
  w84 = arg4[1];
  w83 = w83 * w84;
  w19 = w19 + w83;
  w83 = arg2[72];
  w83 = w83 * w31;
  w85 = arg2[81];
  w85 = w85 * w38;
  w83 = w83 + w85;
  w85 = arg2[90];
  w85 = w85 * w59;
  w83 = w83 + w85;
  w85 = arg4[2];
  w83 = w83 * w85;
  w19 = w19 + w83;
  w39 = w39 * w19;
  w41 = w41 * w31;
  w62 = w62 * w38;
  w41 = w41 + w62;
  w80 = w80 * w77;
  w74 = w74 * w82;
  w80 = w80 - w74;
  w80 = w80 * w59;
  w41 = w41 + w80;
  w4 = w4 * w26;
  w41 = w41 + w4;
  w4 = arg2[73];
  w4 = w4 * w31;
  w80 = arg2[82];
  w80 = w80 * w38;
  w4 = w4 + w80;
  w80 = arg2[91];
  w80 = w80 * w59;
  w4 = w4 + w80;
  w4 = w4 * w78;
  w80 = arg2[74];
  w80 = w80 * w31;
  w80 = w26 + w80;
  w74 = arg2[83];
  w74 = w74 * w38;
  w80 = w80 + w74;
  w74 = arg2[92];
  w74 = w74 * w59;
  w80 = w80 + w74;
  w80 = w80 * w84;
  w4 = w4 + w80;
  w80 = arg2[75];
  w80 = w80 * w31;
  w74 = arg2[84];
  w74 = w74 * w38;
  w80 = w80 + w74;
  w74 = arg2[93];
  w74 = w74 * w59;
  w80 = w80 + w74;
  w80 = w80 * w85;
  w4 = w4 + w80;
  w41 = w41 * w4;
  w39 = w39 + w41;
  w41 = w11 * w31;
  w80 = w52 * w38;
  w41 = w41 + w80;
  w80 = w73 * w59;
  w41 = w41 + w80;
  w12 = w12 * w26;
  w41 = w41 + w12;
  w12 = arg2[76];
  w12 = w12 * w31;
  w80 = arg2[85];
  w80 = w80 * w38;
  w12 = w12 + w80;
  w80 = arg2[94];
  w80 = w80 * w59;
  w12 = w12 + w80;
  w12 = w12 * w78;
  w78 = arg2[77];
  w78 = w78 * w31;
  w80 = arg2[86];
  w80 = w80 * w38;
  w78 = w78 + w80;
  w80 = arg2[95];
  w80 = w80 * w59;
  w78 = w78 + w80;
  w78 = w78 * w84;
  w12 = w12 + w78;
  w78 = arg2[78];
  w78 = w78 * w31;
  w78 = w26 + w78;
  w84 = arg2[87];
  w84 = w84 * w38;
  w78 = w78 + w84;
  w84 = arg2[96];
  w84 = w84 * w59;
  w78 = w78 + w84;
  w78 = w78 * w85;
  w12 = w12 + w78;
  w41 = w41 * w12;
  w39 = w39 + w41;
  w41 = w23 * w39;
  w27 = w27 + w41;
  w41 = w9 * w26;
  w78 = w2 * w31;
  w41 = w41 + w78;
  w78 = w50 * w38;
  w41 = w41 + w78;
  w64 = w43 * w64;
  w57 = w57 * w68;
  w64 = w64 + w57;
  w71 = w71 * w69;
  w64 = w64 + w71;
  w71 = w64 * w66;
  w71 = w50 + w71;
  w71 = w71 * w59;
  w41 = w41 + w71;
  w47 = w47 * w31;
  w71 = w68 * w38;
  w47 = w47 + w71;
  w71 = w43 * w72;
  w57 = w75 * w68;
  w71 = w71 + w57;
  w57 = w76 * w69;
  w71 = w71 + w57;
  w57 = w71 * w77;
  w78 = w43 * w79;
  w68 = w81 * w68;
  w78 = w78 + w68;
  w68 = w60 * w69;
  w78 = w78 + w68;
  w68 = w78 * w82;
  w57 = w57 + w68;
  w57 = w57 * w59;
  w47 = w47 + w57;
  w3 = w3 * w26;
  w47 = w47 + w3;
  w47 = w47 * w19;
  w48 = w48 * w31;
  w69 = w69 * w38;
  w48 = w48 + w69;
  w78 = w78 * w77;
  w71 = w71 * w82;
  w78 = w78 - w71;
  w78 = w78 * w59;
  w48 = w48 + w78;
  w14 = w14 * w26;
  w48 = w48 + w14;
  w48 = w48 * w4;
  w47 = w47 + w48;
  w48 = w6 * w31;
  w14 = w43 * w38;
  w48 = w48 + w14;
  w14 = w64 * w59;
  w48 = w48 + w14;
  w16 = w16 * w26;
  w48 = w48 + w16;
  w48 = w48 * w12;
  w47 = w47 + w48;
  w48 = w8 * w26;
  w16 = w46 * w31;
  w48 = w48 + w16;
  w16 = w67 * w38;
  w48 = w48 + w16;
  w16 = w63 * w66;
  w16 = w67 + w16;
  w16 = w16 * w59;
  w48 = w48 + w16;
  w16 = w47 * w48;
  w37 = w37 * w31;
  w14 = w58 * w38;
  w37 = w37 + w14;
  w72 = w42 * w72;
  w75 = w75 * w58;
  w72 = w72 + w75;
  w76 = w76 * w61;
  w72 = w72 + w76;
  w76 = w72 * w77;
  w79 = w42 * w79;
  w81 = w81 * w58;
  w79 = w79 + w81;
  w60 = w60 * w61;
  w79 = w79 + w60;
  w60 = w79 * w82;
  w76 = w76 + w60;
  w76 = w76 * w59;
  w37 = w37 + w76;
  w76 = w10 * w26;
  w37 = w37 + w76;
  w37 = w37 * w19;
  w40 = w40 * w31;
  w61 = w61 * w38;
  w40 = w40 + w61;
  w79 = w79 * w77;
  w72 = w72 * w82;
  w79 = w79 - w72;
  w79 = w79 * w59;
  w40 = w40 + w79;
  w79 = w0 * w26;
  w40 = w40 + w79;
  w40 = w40 * w4;
  w37 = w37 + w40;
  w15 = w15 * w31;
  w42 = w42 * w38;
  w15 = w15 + w42;
  w42 = w63 * w59;
  w15 = w15 + w42;
  w42 = w1 * w26;
  w15 = w15 + w42;
  w15 = w15 * w12;
  w37 = w37 + w15;
  w15 = w37 * w41;
  w16 = w16 - w15;
  w15 = w41 * w16;
  w27 = w27 + w15;
  w15 = w35 * w31;
  w12 = w56 * w38;
  w15 = w15 + w12;
  w12 = w64 * w67;
  w63 = w63 * w50;
  w12 = w12 - w63;
  w12 = w66 * w12;
  w12 = w56 + w12;
  w12 = w12 * w59;
  w15 = w15 + w12;
  w12 = w15 * w47;
  w27 = w27 - w12;
  w12 = w24 * w26;
  w63 = w34 * w31;
  w12 = w12 + w63;
  w63 = w55 * w38;
  w12 = w12 + w63;
  w63 = w73 * w66;
  w63 = w55 + w63;
  w63 = w63 * w59;
  w12 = w12 + w63;
  w63 = w37 * w12;
  w42 = w39 * w48;
  w63 = w63 - w42;
  w42 = w12 * w63;
  w27 = w27 - w42;
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
  w49 = w1 * w38;
  w21 = w21 + w49;
  w56 = w56 * w53;
  w1 = w1 + w56;
  w56 = w54 * w50;
  w49 = w36 * w55;
  w56 = w56 - w49;
  w49 = w55 * w56;
  w1 = w1 + w49;
  w52 = w52 * w2;
  w43 = w43 * w34;
  w52 = w52 - w43;
  w45 = w45 * w52;
  w45 = w30 + w45;
  w54 = w45 * w54;
  w1 = w1 - w54;
  w70 = w67 * w70;
  w1 = w1 - w70;
  w1 = w1 * w59;
  w21 = w21 + w1;
  w15 = w15 * w37;
  w21 = w21 + w15;
  w15 = w39 * w41;
  w1 = w47 * w12;
  w15 = w15 - w1;
  w12 = w12 * w15;
  w21 = w21 + w12;
  w12 = w30 * w31;
  w1 = w45 * w38;
  w12 = w12 + w1;
  w73 = w73 * w50;
  w64 = w64 * w55;
  w73 = w73 - w64;
  w66 = w66 * w73;
  w66 = w45 + w66;
  w66 = w66 * w59;
  w12 = w12 + w66;
  w39 = w12 * w39;
  w21 = w21 - w39;
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
  w38 = w25 * w38;
  w26 = w26 + w38;
  w45 = w45 * w36;
  w25 = w25 + w45;
  w67 = w67 * w65;
  w25 = w25 + w67;
  w51 = w51 * w53;
  w25 = w25 - w51;
  w50 = w50 * w56;
  w25 = w25 - w50;
  w25 = w25 * w59;
  w26 = w26 + w25;
  w12 = w12 * w47;
  w26 = w26 + w12;
  w48 = w48 * w63;
  w26 = w26 + w48;
  w23 = w23 * w37;
  w26 = w26 - w23;
  w41 = w41 * w15;
  w26 = w26 - w41;
  res0[2] = w26;
}


CASADI_SYMBOL_EXPORT int snakecg_sp3_batch_point_bias_acceleration(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[5];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 87);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 5; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  if (arg[0] && arg[1] && arg[2] && arg[3] && arg[4] && res[0]) {
    /* cos and sin of q[7..9] of 16 samples at a time, then snakecg_sp3_point_bias_acceleration_sincos
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
        snakecg_sp3_point_bias_acceleration_sincos(arg[0] + (i0 + i) * stride[0], arg[1] + (i0 + i) * stride[1], arg[2] + (i0 + i) * stride[2], arg[3] + (i0 + i) * stride[3], arg[4] + (i0 + i) * stride[4], ca + i * na, sa + i * na, res[0] + (i0 + i) * 3);
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
      if (snakecg_sp3_point_bias_acceleration(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
    }
  }
  free(iw);
  free(w);
  return status;
}
