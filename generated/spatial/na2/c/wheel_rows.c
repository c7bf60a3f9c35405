/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for wheel_rows() of
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
  #define CASADI_PREFIX(ID) snakecg_sp2_wheel_rows_ ## ID
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
CASADI_SYMBOL_EXPORT void snakecg_sp2_wheel_rows_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp2_wheel_rows_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp2_wheel_rows_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {9, 1, 1};
static const casadi_int casadi_s1[3] = {8, 1, 1};
static const casadi_int casadi_s2[3] = {120, 1, 1};
static const casadi_int casadi_s3[3] = {3, 8, 1};
static const casadi_int casadi_s4[3] = {3, 1, 1};

/* snakecg_sp2_wheel_rows:(q[9],v[8],K[120],wheel_points[9],wheel_heading[9])->(A[3x8],adot_v[3]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43, a44, a45, a46, a47;
  casadi_real a48, a49, a50, a51, a52, a53, a54, a55, a56, a57, a58, a59;
  casadi_real a60, a61, a62, a63, a64, a65, a66, a67, a68, a69, a70, a71;
  casadi_real a72, a73, a74, a75, a76, a77, a78, a79, a80, a81, a82, a83;
  casadi_real a84, a85, a86, a87, a88, a89, a90, a91, a92, a93, a94, a95;
  a00=arg[0]? arg[0][6] : 0;
  a01=(2.*a00);
  a02=arg[0]? arg[0][5] : 0;
  a03=(a01*a02);
  a04=arg[0]? arg[0][3] : 0;
  a05=(2.*a04);
  a06=arg[0]? arg[0][4] : 0;
  a07=(a05*a06);
  a03=(a03+a07);
  a08=1.;
  a09=-2.;
  a10=casadi_sq(a06);
  a10=(a09*a10);
  a11=(a08+a10);
  a12=casadi_sq(a02);
  a12=(a09*a12);
  a11=(a11+a12);
  a13=arg[4]? arg[4][0] : 0;
  a14=(a11*a13);
  a00=(a09*a00);
  a15=(a00*a02);
  a15=(a15+a07);
  a07=arg[4]? arg[4][1] : 0;
  a16=(a15*a07);
  a14=(a14+a16);
  a16=(a01*a06);
  a05=(a05*a02);
  a16=(a16+a05);
  a17=arg[4]? arg[4][2] : 0;
  a18=(a16*a17);
  a14=(a14+a18);
  a18=casadi_sq(a14);
  a19=(a03*a13);
  a20=casadi_sq(a04);
  a09=(a09*a20);
  a08=(a08+a09);
  a12=(a08+a12);
  a09=(a12*a07);
  a19=(a19+a09);
  a09=(a00*a04);
  a20=(2.*a06);
  a20=(a20*a02);
  a09=(a09+a20);
  a02=(a09*a17);
  a19=(a19+a02);
  a02=casadi_sq(a19);
  a18=(a18+a02);
  a02=-5.0000000000000000e-01;
  a18=pow(a18,a02);
  a21=(a14*a18);
  a22=(a03*a21);
  a23=(a19*a18);
  a24=(a11*a23);
  a22=(a22-a24);
  if (res[0]!=0) res[0][0]=a22;
  a22=arg[2]? arg[2][75] : 0;
  a24=(a22*a11);
  a25=arg[2]? arg[2][76] : 0;
  a26=(a25*a15);
  a24=(a24+a26);
  a26=arg[2]? arg[2][77] : 0;
  a27=(a26*a16);
  a24=(a24+a27);
  a27=arg[2]? arg[2][57] : 0;
  a28=arg[4]? arg[4][3] : 0;
  a29=(a27*a28);
  a30=arg[2]? arg[2][58] : 0;
  a31=arg[4]? arg[4][4] : 0;
  a32=(a30*a31);
  a29=(a29+a32);
  a32=arg[2]? arg[2][59] : 0;
  a33=arg[4]? arg[4][5] : 0;
  a34=(a32*a33);
  a29=(a29+a34);
  a34=(a24*a29);
  a35=arg[2]? arg[2][69] : 0;
  a36=(a35*a11);
  a37=arg[2]? arg[2][70] : 0;
  a38=(a37*a15);
  a36=(a36+a38);
  a38=arg[2]? arg[2][71] : 0;
  a39=(a38*a16);
  a36=(a36+a39);
  a39=arg[0]? arg[0][7] : 0;
  a40=cos(a39);
  a41=(a36*a40);
  a42=arg[2]? arg[2][72] : 0;
  a43=(a42*a11);
  a44=arg[2]? arg[2][73] : 0;
  a45=(a44*a15);
  a43=(a43+a45);
  a45=arg[2]? arg[2][74] : 0;
  a46=(a45*a16);
  a43=(a43+a46);
  a39=sin(a39);
  a46=(a43*a39);
  a41=(a41+a46);
  a46=arg[2]? arg[2][51] : 0;
  a47=(a46*a28);
  a48=arg[2]? arg[2][52] : 0;
  a49=(a48*a31);
  a47=(a47+a49);
  a49=arg[2]? arg[2][53] : 0;
  a50=(a49*a33);
  a47=(a47+a50);
  a50=(a41*a47);
  a34=(a34+a50);
  a43=(a43*a40);
  a36=(a36*a39);
  a43=(a43-a36);
  a36=arg[2]? arg[2][54] : 0;
  a28=(a36*a28);
  a50=arg[2]? arg[2][55] : 0;
  a31=(a50*a31);
  a28=(a28+a31);
  a31=arg[2]? arg[2][56] : 0;
  a33=(a31*a33);
  a28=(a28+a33);
  a33=(a43*a28);
  a34=(a34+a33);
  a33=casadi_sq(a34);
  a51=(a22*a03);
  a52=(a25*a12);
  a51=(a51+a52);
  a52=(a26*a09);
  a51=(a51+a52);
  a52=(a51*a29);
  a53=(a35*a03);
  a54=(a37*a12);
  a53=(a53+a54);
  a54=(a38*a09);
  a53=(a53+a54);
  a54=(a53*a40);
  a55=(a42*a03);
  a56=(a44*a12);
  a55=(a55+a56);
  a56=(a45*a09);
  a55=(a55+a56);
  a56=(a55*a39);
  a54=(a54+a56);
  a56=(a54*a47);
  a52=(a52+a56);
  a55=(a55*a40);
  a53=(a53*a39);
  a55=(a55-a53);
  a53=(a55*a28);
  a52=(a52+a53);
  a53=casadi_sq(a52);
  a33=(a33+a53);
  a33=pow(a33,a02);
  a53=(a34*a33);
  a56=(a03*a53);
  a57=(a52*a33);
  a58=(a11*a57);
  a56=(a56-a58);
  if (res[0]!=0) res[0][1]=a56;
  a56=arg[2]? arg[2][86] : 0;
  a58=(a24*a56);
  a59=arg[2]? arg[2][84] : 0;
  a60=(a59*a41);
  a58=(a58+a60);
  a60=arg[2]? arg[2][85] : 0;
  a61=(a60*a43);
  a58=(a58+a61);
  a61=arg[2]? arg[2][66] : 0;
  a62=arg[4]? arg[4][6] : 0;
  a63=(a61*a62);
  a64=arg[2]? arg[2][67] : 0;
  a65=arg[4]? arg[4][7] : 0;
  a66=(a64*a65);
  a63=(a63+a66);
  a66=arg[2]? arg[2][68] : 0;
  a67=arg[4]? arg[4][8] : 0;
  a68=(a66*a67);
  a63=(a63+a68);
  a68=(a58*a63);
  a69=arg[2]? arg[2][80] : 0;
  a70=(a24*a69);
  a71=arg[2]? arg[2][78] : 0;
  a72=(a71*a41);
  a70=(a70+a72);
  a72=arg[2]? arg[2][79] : 0;
  a73=(a72*a43);
  a70=(a70+a73);
  a73=arg[0]? arg[0][8] : 0;
  a74=cos(a73);
  a75=(a70*a74);
  a76=arg[2]? arg[2][83] : 0;
  a77=(a24*a76);
  a78=arg[2]? arg[2][81] : 0;
  a79=(a78*a41);
  a77=(a77+a79);
  a79=arg[2]? arg[2][82] : 0;
  a80=(a79*a43);
  a77=(a77+a80);
  a73=sin(a73);
  a80=(a77*a73);
  a75=(a75+a80);
  a80=arg[2]? arg[2][60] : 0;
  a81=(a80*a62);
  a82=arg[2]? arg[2][61] : 0;
  a83=(a82*a65);
  a81=(a81+a83);
  a83=arg[2]? arg[2][62] : 0;
  a84=(a83*a67);
  a81=(a81+a84);
  a84=(a75*a81);
  a68=(a68+a84);
  a77=(a77*a74);
  a70=(a70*a73);
  a77=(a77-a70);
  a70=arg[2]? arg[2][63] : 0;
  a62=(a70*a62);
  a84=arg[2]? arg[2][64] : 0;
  a65=(a84*a65);
  a62=(a62+a65);
  a65=arg[2]? arg[2][65] : 0;
  a67=(a65*a67);
  a62=(a62+a67);
  a67=(a77*a62);
  a68=(a68+a67);
  a67=casadi_sq(a68);
  a85=(a51*a56);
  a86=(a59*a54);
  a85=(a85+a86);
  a86=(a60*a55);
  a85=(a85+a86);
  a86=(a85*a63);
  a87=(a51*a69);
  a88=(a71*a54);
  a87=(a87+a88);
  a88=(a72*a55);
  a87=(a87+a88);
  a88=(a87*a74);
  a89=(a51*a76);
  a90=(a78*a54);
  a89=(a89+a90);
  a90=(a79*a55);
  a89=(a89+a90);
  a90=(a89*a73);
  a88=(a88+a90);
  a90=(a88*a81);
  a86=(a86+a90);
  a89=(a89*a74);
  a87=(a87*a73);
  a89=(a89-a87);
  a87=(a89*a62);
  a86=(a86+a87);
  a87=casadi_sq(a86);
  a67=(a67+a87);
  a67=pow(a67,a02);
  a02=(a68*a67);
  a87=(a03*a02);
  a90=(a86*a67);
  a91=(a11*a90);
  a87=(a87-a91);
  if (res[0]!=0) res[0][2]=a87;
  a87=(a12*a21);
  a91=(a15*a23);
  a87=(a87-a91);
  if (res[0]!=0) res[0][3]=a87;
  a87=(a12*a53);
  a91=(a15*a57);
  a87=(a87-a91);
  if (res[0]!=0) res[0][4]=a87;
  a87=(a12*a02);
  a91=(a15*a90);
  a87=(a87-a91);
  if (res[0]!=0) res[0][5]=a87;
  a87=(a09*a21);
  a91=(a16*a23);
  a87=(a87-a91);
  if (res[0]!=0) res[0][6]=a87;
  a87=(a09*a53);
  a91=(a16*a57);
  a87=(a87-a91);
  if (res[0]!=0) res[0][7]=a87;
  a87=(a09*a02);
  a91=(a16*a90);
  a87=(a87-a91);
  if (res[0]!=0) res[0][8]=a87;
  a00=(a00*a06);
  a00=(a00+a05);
  a05=arg[3]? arg[3][0] : 0;
  a06=(a11*a05);
  a87=arg[3]? arg[3][1] : 0;
  a91=(a15*a87);
  a06=(a06+a91);
  a91=arg[3]? arg[3][2] : 0;
  a92=(a16*a91);
  a06=(a06+a92);
  a92=(a00*a06);
  a93=(a00*a05);
  a01=(a01*a04);
  a01=(a01+a20);
  a20=(a01*a87);
  a93=(a93+a20);
  a08=(a08+a10);
  a10=(a08*a91);
  a93=(a93+a10);
  a10=(a11*a93);
  a92=(a92-a10);
  a92=(a21*a92);
  a10=(a03*a93);
  a05=(a03*a05);
  a87=(a12*a87);
  a05=(a05+a87);
  a91=(a09*a91);
  a05=(a05+a91);
  a91=(a00*a05);
  a10=(a10-a91);
  a10=(a23*a10);
  a92=(a92-a10);
  if (res[0]!=0) res[0][9]=a92;
  a92=arg[2]? arg[2][87] : 0;
  a10=(a11*a92);
  a91=arg[2]? arg[2][88] : 0;
  a87=(a15*a91);
  a10=(a10+a87);
  a87=arg[2]? arg[2][89] : 0;
  a20=(a16*a87);
  a10=(a10+a20);
  a20=arg[0]? arg[0][0] : 0;
  a04=(a10+a20);
  a94=arg[3]? arg[3][3] : 0;
  a27=(a27*a94);
  a95=arg[3]? arg[3][4] : 0;
  a30=(a30*a95);
  a27=(a27+a30);
  a30=arg[3]? arg[3][5] : 0;
  a32=(a32*a30);
  a27=(a27+a32);
  a32=(a24*a27);
  a46=(a46*a94);
  a48=(a48*a95);
  a46=(a46+a48);
  a49=(a49*a30);
  a46=(a46+a49);
  a49=(a41*a46);
  a32=(a32+a49);
  a36=(a36*a94);
  a50=(a50*a95);
  a36=(a36+a50);
  a31=(a31*a30);
  a36=(a36+a31);
  a31=(a43*a36);
  a32=(a32+a31);
  a31=(a04+a32);
  a31=(a31-a20);
  a30=(a00*a31);
  a50=(a00*a92);
  a95=(a01*a91);
  a50=(a50+a95);
  a95=(a08*a87);
  a50=(a50+a95);
  a95=arg[0]? arg[0][2] : 0;
  a94=(a50+a95);
  a22=(a22*a00);
  a25=(a25*a01);
  a22=(a22+a25);
  a26=(a26*a08);
  a22=(a22+a26);
  a26=(a22*a27);
  a35=(a35*a00);
  a37=(a37*a01);
  a35=(a35+a37);
  a38=(a38*a08);
  a35=(a35+a38);
  a38=(a35*a40);
  a42=(a42*a00);
  a44=(a44*a01);
  a42=(a42+a44);
  a45=(a45*a08);
  a42=(a42+a45);
  a45=(a42*a39);
  a38=(a38+a45);
  a45=(a38*a46);
  a26=(a26+a45);
  a42=(a42*a40);
  a35=(a35*a39);
  a42=(a42-a35);
  a35=(a42*a36);
  a26=(a26+a35);
  a35=(a94+a26);
  a35=(a35-a95);
  a39=(a11*a35);
  a30=(a30-a39);
  a30=(a53*a30);
  a39=(a03*a35);
  a92=(a03*a92);
  a91=(a12*a91);
  a92=(a92+a91);
  a87=(a09*a87);
  a92=(a92+a87);
  a87=arg[0]? arg[0][1] : 0;
  a91=(a92+a87);
  a27=(a51*a27);
  a46=(a54*a46);
  a27=(a27+a46);
  a36=(a55*a36);
  a27=(a27+a36);
  a36=(a91+a27);
  a36=(a36-a87);
  a46=(a00*a36);
  a39=(a39-a46);
  a39=(a57*a39);
  a30=(a30-a39);
  if (res[0]!=0) res[0][10]=a30;
  a30=arg[2]? arg[2][92] : 0;
  a39=(a24*a30);
  a46=arg[2]? arg[2][90] : 0;
  a41=(a41*a46);
  a39=(a39+a41);
  a41=arg[2]? arg[2][91] : 0;
  a43=(a43*a41);
  a39=(a39+a43);
  a43=(a39+a04);
  a40=arg[3]? arg[3][6] : 0;
  a61=(a61*a40);
  a45=arg[3]? arg[3][7] : 0;
  a64=(a64*a45);
  a61=(a61+a64);
  a64=arg[3]? arg[3][8] : 0;
  a66=(a66*a64);
  a61=(a61+a66);
  a66=(a58*a61);
  a80=(a80*a40);
  a82=(a82*a45);
  a80=(a80+a82);
  a83=(a83*a64);
  a80=(a80+a83);
  a75=(a75*a80);
  a66=(a66+a75);
  a70=(a70*a40);
  a84=(a84*a45);
  a70=(a70+a84);
  a65=(a65*a64);
  a70=(a70+a65);
  a77=(a77*a70);
  a66=(a66+a77);
  a43=(a43+a66);
  a20=(a43-a20);
  a77=(a00*a20);
  a65=(a22*a30);
  a64=(a38*a46);
  a65=(a65+a64);
  a64=(a42*a41);
  a65=(a65+a64);
  a64=(a65+a94);
  a56=(a22*a56);
  a59=(a59*a38);
  a56=(a56+a59);
  a60=(a60*a42);
  a56=(a56+a60);
  a60=(a56*a61);
  a69=(a22*a69);
  a71=(a71*a38);
  a69=(a69+a71);
  a72=(a72*a42);
  a69=(a69+a72);
  a72=(a69*a74);
  a76=(a22*a76);
  a78=(a78*a38);
  a76=(a76+a78);
  a79=(a79*a42);
  a76=(a76+a79);
  a79=(a76*a73);
  a72=(a72+a79);
  a79=(a72*a80);
  a60=(a60+a79);
  a76=(a76*a74);
  a69=(a69*a73);
  a76=(a76-a69);
  a69=(a76*a70);
  a60=(a60+a69);
  a64=(a64+a60);
  a95=(a64-a95);
  a69=(a11*a95);
  a77=(a77-a69);
  a77=(a02*a77);
  a69=(a03*a95);
  a30=(a51*a30);
  a54=(a54*a46);
  a30=(a30+a54);
  a55=(a55*a41);
  a30=(a30+a55);
  a55=(a30+a91);
  a61=(a85*a61);
  a88=(a88*a80);
  a61=(a61+a88);
  a89=(a89*a70);
  a61=(a61+a89);
  a55=(a55+a61);
  a87=(a55-a87);
  a89=(a00*a87);
  a69=(a69-a89);
  a69=(a90*a69);
  a77=(a77-a69);
  if (res[0]!=0) res[0][11]=a77;
  a77=(a01*a06);
  a69=(a15*a93);
  a77=(a77-a69);
  a77=(a21*a77);
  a69=(a12*a93);
  a89=(a01*a05);
  a69=(a69-a89);
  a69=(a23*a69);
  a77=(a77-a69);
  if (res[0]!=0) res[0][12]=a77;
  a77=(a01*a31);
  a69=(a15*a35);
  a77=(a77-a69);
  a77=(a53*a77);
  a69=(a12*a35);
  a89=(a01*a36);
  a69=(a69-a89);
  a69=(a57*a69);
  a77=(a77-a69);
  if (res[0]!=0) res[0][13]=a77;
  a77=(a01*a20);
  a69=(a15*a95);
  a77=(a77-a69);
  a77=(a02*a77);
  a69=(a12*a95);
  a89=(a01*a87);
  a69=(a69-a89);
  a69=(a90*a69);
  a77=(a77-a69);
  if (res[0]!=0) res[0][14]=a77;
  a77=(a08*a06);
  a69=(a16*a93);
  a77=(a77-a69);
  a77=(a21*a77);
  a69=(a09*a93);
  a89=(a08*a05);
  a69=(a69-a89);
  a69=(a23*a69);
  a77=(a77-a69);
  if (res[0]!=0) res[0][15]=a77;
  a31=(a08*a31);
  a77=(a16*a35);
  a31=(a31-a77);
  a31=(a53*a31);
  a35=(a09*a35);
  a36=(a08*a36);
  a35=(a35-a36);
  a35=(a57*a35);
  a31=(a31-a35);
  if (res[0]!=0) res[0][16]=a31;
  a20=(a08*a20);
  a31=(a16*a95);
  a20=(a20-a31);
  a20=(a02*a20);
  a95=(a09*a95);
  a87=(a08*a87);
  a95=(a95-a87);
  a95=(a90*a95);
  a20=(a20-a95);
  if (res[0]!=0) res[0][17]=a20;
  a20=0.;
  if (res[0]!=0) res[0][18]=a20;
  a95=(a22*a32);
  a87=(a24*a26);
  a95=(a95-a87);
  a95=(a53*a95);
  a87=(a51*a26);
  a31=(a22*a27);
  a87=(a87-a31);
  a87=(a57*a87);
  a95=(a95-a87);
  if (res[0]!=0) res[0][19]=a95;
  a43=(a43-a04);
  a43=(a22*a43);
  a64=(a64-a94);
  a94=(a24*a64);
  a43=(a43-a94);
  a43=(a02*a43);
  a64=(a51*a64);
  a55=(a55-a91);
  a55=(a22*a55);
  a64=(a64-a55);
  a64=(a90*a64);
  a43=(a43-a64);
  if (res[0]!=0) res[0][20]=a43;
  if (res[0]!=0) res[0][21]=a20;
  if (res[0]!=0) res[0][22]=a20;
  a20=(a56*a66);
  a43=(a58*a60);
  a20=(a20-a43);
  a20=(a02*a20);
  a43=(a85*a60);
  a64=(a56*a61);
  a43=(a43-a64);
  a43=(a90*a43);
  a20=(a20-a43);
  if (res[0]!=0) res[0][23]=a20;
  a20=arg[1]? arg[1][3] : 0;
  a43=(a00*a20);
  a64=arg[1]? arg[1][4] : 0;
  a55=(a01*a64);
  a43=(a43+a55);
  a55=arg[1]? arg[1][5] : 0;
  a91=(a08*a55);
  a43=(a43+a91);
  a91=arg[1]? arg[1][0] : 0;
  a94=(a11*a91);
  a04=arg[1]? arg[1][1] : 0;
  a95=(a15*a04);
  a94=(a94+a95);
  a95=arg[1]? arg[1][2] : 0;
  a87=(a16*a95);
  a94=(a94+a87);
  a87=(a43*a94);
  a11=(a11*a20);
  a15=(a15*a64);
  a11=(a11+a15);
  a16=(a16*a55);
  a11=(a11+a16);
  a16=(a00*a91);
  a15=(a01*a04);
  a16=(a16+a15);
  a15=(a08*a95);
  a16=(a16+a15);
  a15=(a11*a16);
  a87=(a87-a15);
  a20=(a03*a20);
  a64=(a12*a64);
  a20=(a20+a64);
  a55=(a09*a55);
  a20=(a20+a55);
  a55=(a20*a93);
  a64=(a43*a05);
  a15=(a55-a64);
  a15=(a43*a15);
  a15=(a87+a15);
  a05=(a11*a05);
  a31=(a20*a06);
  a05=(a05-a31);
  a31=(a11*a05);
  a15=(a15-a31);
  a15=(a15*a21);
  a16=(a20*a16);
  a03=(a03*a91);
  a12=(a12*a04);
  a03=(a03+a12);
  a09=(a09*a95);
  a03=(a03+a09);
  a09=(a43*a03);
  a16=(a16-a09);
  a05=(a20*a05);
  a05=(a16+a05);
  a06=(a43*a06);
  a93=(a11*a93);
  a09=(a06-a93);
  a09=(a43*a09);
  a05=(a05-a09);
  a05=(a05*a23);
  a15=(a15-a05);
  a55=(a94+a55);
  a55=(a55-a64);
  a55=(a55*a18);
  a00=(a00*a13);
  a01=(a01*a07);
  a00=(a00+a01);
  a08=(a08*a17);
  a00=(a00+a08);
  a08=(a20*a00);
  a19=(a43*a19);
  a08=(a08-a19);
  a19=(a08*a21);
  a14=(a43*a14);
  a00=(a11*a00);
  a14=(a14-a00);
  a00=(a14*a23);
  a19=(a19+a00);
  a23=(a19*a23);
  a23=(a23-a14);
  a55=(a55*a23);
  a15=(a15+a55);
  a06=(a03+a06);
  a06=(a06-a93);
  a06=(a06*a18);
  a19=(a19*a21);
  a08=(a08-a19);
  a06=(a06*a08);
  a15=(a15+a06);
  if (res[1]!=0) res[1][0]=a15;
  a15=(a50*a20);
  a06=(a92*a43);
  a08=(a15-a06);
  a08=(a43*a08);
  a87=(a87+a08);
  a92=(a92*a11);
  a08=(a10*a20);
  a92=(a92-a08);
  a08=(a11*a92);
  a87=(a87-a08);
  a08=arg[1]? arg[1][6] : 0;
  a19=(a51*a11);
  a21=(a24*a20);
  a19=(a19-a21);
  a19=(a08*a19);
  a21=(a19*a32);
  a21=(a87+a21);
  a18=(a22*a08);
  a18=(a43+a18);
  a93=(a51*a08);
  a93=(a20+a93);
  a55=(a93*a26);
  a23=(a18*a27);
  a14=(a55-a23);
  a14=(a18*a14);
  a21=(a21+a14);
  a14=(a22*a20);
  a51=(a51*a43);
  a14=(a14-a51);
  a14=(a08*a14);
  a51=(a14*a26);
  a21=(a21-a51);
  a51=(a24*a08);
  a51=(a11+a51);
  a00=(a51*a27);
  a17=(a93*a32);
  a00=(a00-a17);
  a17=(a51*a00);
  a21=(a21-a17);
  a21=(a21*a53);
  a20=(a20*a92);
  a16=(a16+a20);
  a10=(a10*a43);
  a50=(a50*a11);
  a20=(a10-a50);
  a20=(a43*a20);
  a16=(a16-a20);
  a24=(a24*a43);
  a11=(a22*a11);
  a24=(a24-a11);
  a08=(a08*a24);
  a24=(a08*a26);
  a24=(a16+a24);
  a00=(a93*a00);
  a24=(a24+a00);
  a27=(a19*a27);
  a24=(a24-a27);
  a32=(a18*a32);
  a26=(a51*a26);
  a27=(a32-a26);
  a27=(a18*a27);
  a24=(a24-a27);
  a24=(a24*a57);
  a21=(a21-a24);
  a94=(a94+a15);
  a94=(a94-a06);
  a55=(a94+a55);
  a55=(a55-a23);
  a55=(a55*a33);
  a22=(a22*a29);
  a38=(a38*a47);
  a22=(a22+a38);
  a42=(a42*a28);
  a22=(a22+a42);
  a42=(a93*a22);
  a52=(a18*a52);
  a42=(a42-a52);
  a52=(a42*a53);
  a34=(a18*a34);
  a22=(a51*a22);
  a34=(a34-a22);
  a22=(a34*a57);
  a52=(a52+a22);
  a57=(a52*a57);
  a57=(a57-a34);
  a55=(a55*a57);
  a21=(a21+a55);
  a03=(a03+a10);
  a03=(a03-a50);
  a32=(a03+a32);
  a32=(a32-a26);
  a32=(a32*a33);
  a52=(a52*a53);
  a42=(a42-a52);
  a32=(a32*a42);
  a21=(a21+a32);
  if (res[1]!=0) res[1][1]=a21;
  a21=(a19*a39);
  a87=(a87+a21);
  a21=(a65*a93);
  a32=(a30*a18);
  a42=(a21-a32);
  a42=(a18*a42);
  a87=(a87+a42);
  a42=(a14*a65);
  a87=(a87-a42);
  a42=(a30*a51);
  a52=(a39*a93);
  a42=(a42-a52);
  a52=(a51*a42);
  a87=(a87-a52);
  a52=arg[1]? arg[1][7] : 0;
  a53=(a85*a51);
  a33=(a58*a93);
  a53=(a53-a33);
  a53=(a52*a53);
  a53=(a19+a53);
  a33=(a53*a66);
  a87=(a87+a33);
  a33=(a56*a52);
  a33=(a18+a33);
  a26=(a85*a52);
  a26=(a93+a26);
  a50=(a26*a60);
  a10=(a33*a61);
  a55=(a50-a10);
  a55=(a33*a55);
  a87=(a87+a55);
  a55=(a56*a93);
  a85=(a85*a18);
  a55=(a55-a85);
  a55=(a52*a55);
  a14=(a14+a55);
  a14=(a14*a60);
  a87=(a87-a14);
  a14=(a58*a52);
  a14=(a51+a14);
  a55=(a14*a61);
  a85=(a26*a66);
  a55=(a55-a85);
  a85=(a14*a55);
  a87=(a87-a85);
  a87=(a87*a02);
  a85=(a08*a65);
  a16=(a16+a85);
  a93=(a93*a42);
  a16=(a16+a93);
  a19=(a19*a30);
  a16=(a16-a19);
  a39=(a39*a18);
  a65=(a65*a51);
  a19=(a39-a65);
  a19=(a18*a19);
  a16=(a16-a19);
  a58=(a58*a18);
  a51=(a56*a51);
  a58=(a58-a51);
  a52=(a52*a58);
  a08=(a08+a52);
  a08=(a08*a60);
  a16=(a16+a08);
  a55=(a26*a55);
  a16=(a16+a55);
  a53=(a53*a61);
  a16=(a16-a53);
  a66=(a33*a66);
  a60=(a14*a60);
  a53=(a66-a60);
  a53=(a33*a53);
  a16=(a16-a53);
  a16=(a16*a90);
  a87=(a87-a16);
  a94=(a94+a21);
  a94=(a94-a32);
  a94=(a94+a50);
  a94=(a94-a10);
  a94=(a94*a67);
  a56=(a56*a63);
  a72=(a72*a81);
  a56=(a56+a72);
  a76=(a76*a62);
  a56=(a56+a76);
  a26=(a26*a56);
  a86=(a33*a86);
  a26=(a26-a86);
  a86=(a26*a02);
  a33=(a33*a68);
  a14=(a14*a56);
  a33=(a33-a14);
  a14=(a33*a90);
  a86=(a86+a14);
  a90=(a86*a90);
  a90=(a90-a33);
  a94=(a94*a90);
  a87=(a87+a94);
  a03=(a03+a39);
  a03=(a03-a65);
  a03=(a03+a66);
  a03=(a03-a60);
  a03=(a03*a67);
  a86=(a86*a02);
  a26=(a26-a86);
  a03=(a03*a26);
  a87=(a87+a03);
  if (res[1]!=0) res[1][2]=a87;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_wheel_rows(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_wheel_rows_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_wheel_rows_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_wheel_rows_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp2_wheel_rows_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_wheel_rows_n_in(void) { return 5;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp2_wheel_rows_n_out(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp2_wheel_rows_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_wheel_rows_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "v";
    case 2: return "K";
    case 3: return "wheel_points";
    case 4: return "wheel_heading";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp2_wheel_rows_name_out(casadi_int i) {
  switch (i) {
    case 0: return "A";
    case 1: return "adot_v";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_wheel_rows_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s0;
    case 4: return casadi_s0;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp2_wheel_rows_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s3;
    case 1: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_wheel_rows_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5;
  if (sz_res) *sz_res = 2;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp2_wheel_rows_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 5*sizeof(const casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_sp2_batch_wheel_rows(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[5];
  casadi_real* r[2];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 97);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 5; ++k) a[k] = 0;
  for (k = 0; k < 2; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    r[0] = res[0] + i * 24;
    r[1] = res[1] + i * 3;
    if (snakecg_sp2_wheel_rows(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
