/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for scene_kinematics() of
 * generated/na3/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive --checked-in
 * spec sha256: 69686744596b549bcd3f0673408c86c5f2701602d7e0095fc6e56d39f6e4f511
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_na3_scene_kinematics_ ## ID
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

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_na3_scene_kinematics_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_na3_scene_kinematics_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_na3_scene_kinematics_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {6, 1, 1};
static const casadi_int casadi_s1[3] = {35, 1, 1};
static const casadi_int casadi_s2[3] = {3, 4, 1};
static const casadi_int casadi_s3[3] = {12, 6, 1};
static const casadi_int casadi_s4[3] = {6, 6, 1};
static const casadi_int casadi_s5[3] = {2, 4, 1};

/* snakecg_na3_scene_kinematics:(q[6],K[35])->(poses[3x4],J[12x6],M[6x6],cs[2x4]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a01=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a01;
  a02=arg[0]? arg[0][2] : 0;
  if (res[0]!=0) res[0][2]=a02;
  a03=cos(a02);
  a04=arg[1]? arg[1][4] : 0;
  a05=arg[1]? arg[1][12] : 0;
  a04=(a04-a05);
  a05=(a03*a04);
  a06=(a05+a00);
  a07=arg[0]? arg[0][3] : 0;
  a08=cos(a07);
  a09=(a03*a08);
  a10=sin(a02);
  a11=sin(a07);
  a12=(a10*a11);
  a09=(a09-a12);
  a12=arg[1]? arg[1][13] : 0;
  a13=(a09*a12);
  a14=(a06+a13);
  if (res[0]!=0) res[0][3]=a14;
  a04=(a04*a10);
  a15=(a04+a01);
  a11=(a03*a11);
  a08=(a08*a10);
  a11=(a11+a08);
  a08=(a11*a12);
  a16=(a15+a08);
  if (res[0]!=0) res[0][4]=a16;
  a07=(a07+a02);
  if (res[0]!=0) res[0][5]=a07;
  a02=arg[1]? arg[1][5] : 0;
  a12=(a02-a12);
  a17=(a09*a12);
  a17=(a14+a17);
  a18=arg[0]? arg[0][4] : 0;
  a19=cos(a18);
  a20=(a09*a19);
  a21=sin(a18);
  a22=(a11*a21);
  a20=(a20-a22);
  a22=arg[1]? arg[1][14] : 0;
  a23=(a20*a22);
  a24=(a17+a23);
  if (res[0]!=0) res[0][6]=a24;
  a12=(a12*a11);
  a12=(a16+a12);
  a21=(a09*a21);
  a19=(a19*a11);
  a21=(a21+a19);
  a19=(a21*a22);
  a25=(a12+a19);
  if (res[0]!=0) res[0][7]=a25;
  a07=(a07+a18);
  if (res[0]!=0) res[0][8]=a07;
  a18=arg[1]? arg[1][6] : 0;
  a22=(a18-a22);
  a26=(a20*a22);
  a26=(a24+a26);
  a27=arg[0]? arg[0][5] : 0;
  a28=cos(a27);
  a29=(a20*a28);
  a30=sin(a27);
  a31=(a21*a30);
  a29=(a29-a31);
  a31=arg[1]? arg[1][15] : 0;
  a32=(a29*a31);
  a26=(a26+a32);
  if (res[0]!=0) res[0][9]=a26;
  a22=(a22*a21);
  a22=(a25+a22);
  a30=(a20*a30);
  a28=(a28*a21);
  a30=(a30+a28);
  a31=(a30*a31);
  a22=(a22+a31);
  if (res[0]!=0) res[0][10]=a22;
  a07=(a07+a27);
  if (res[0]!=0) res[0][11]=a07;
  a07=1.;
  if (res[1]!=0) res[1][0]=a07;
  a27=0.;
  if (res[1]!=0) res[1][1]=a27;
  if (res[1]!=0) res[1][2]=a27;
  if (res[1]!=0) res[1][3]=a07;
  if (res[1]!=0) res[1][4]=a27;
  if (res[1]!=0) res[1][5]=a27;
  if (res[1]!=0) res[1][6]=a07;
  if (res[1]!=0) res[1][7]=a27;
  if (res[1]!=0) res[1][8]=a27;
  if (res[1]!=0) res[1][9]=a07;
  if (res[1]!=0) res[1][10]=a27;
  if (res[1]!=0) res[1][11]=a27;
  if (res[1]!=0) res[1][12]=a27;
  if (res[1]!=0) res[1][13]=a07;
  if (res[1]!=0) res[1][14]=a27;
  if (res[1]!=0) res[1][15]=a27;
  if (res[1]!=0) res[1][16]=a07;
  if (res[1]!=0) res[1][17]=a27;
  if (res[1]!=0) res[1][18]=a27;
  if (res[1]!=0) res[1][19]=a07;
  if (res[1]!=0) res[1][20]=a27;
  if (res[1]!=0) res[1][21]=a27;
  if (res[1]!=0) res[1][22]=a07;
  if (res[1]!=0) res[1][23]=a27;
  if (res[1]!=0) res[1][24]=a27;
  if (res[1]!=0) res[1][25]=a27;
  if (res[1]!=0) res[1][26]=a07;
  a16=(a01-a16);
  if (res[1]!=0) res[1][27]=a16;
  a14=(a14-a00);
  if (res[1]!=0) res[1][28]=a14;
  if (res[1]!=0) res[1][29]=a07;
  a14=(a01-a25);
  if (res[1]!=0) res[1][30]=a14;
  a14=(a24-a00);
  if (res[1]!=0) res[1][31]=a14;
  if (res[1]!=0) res[1][32]=a07;
  a01=(a01-a22);
  if (res[1]!=0) res[1][33]=a01;
  a00=(a26-a00);
  if (res[1]!=0) res[1][34]=a00;
  if (res[1]!=0) res[1][35]=a07;
  if (res[1]!=0) res[1][36]=a27;
  if (res[1]!=0) res[1][37]=a27;
  if (res[1]!=0) res[1][38]=a27;
  a08=(-a08);
  if (res[1]!=0) res[1][39]=a08;
  if (res[1]!=0) res[1][40]=a13;
  if (res[1]!=0) res[1][41]=a07;
  a25=(a15-a25);
  if (res[1]!=0) res[1][42]=a25;
  a24=(a24-a06);
  if (res[1]!=0) res[1][43]=a24;
  if (res[1]!=0) res[1][44]=a07;
  a15=(a15-a22);
  if (res[1]!=0) res[1][45]=a15;
  a06=(a26-a06);
  if (res[1]!=0) res[1][46]=a06;
  if (res[1]!=0) res[1][47]=a07;
  if (res[1]!=0) res[1][48]=a27;
  if (res[1]!=0) res[1][49]=a27;
  if (res[1]!=0) res[1][50]=a27;
  if (res[1]!=0) res[1][51]=a27;
  if (res[1]!=0) res[1][52]=a27;
  if (res[1]!=0) res[1][53]=a27;
  a19=(-a19);
  if (res[1]!=0) res[1][54]=a19;
  if (res[1]!=0) res[1][55]=a23;
  if (res[1]!=0) res[1][56]=a07;
  a12=(a12-a22);
  if (res[1]!=0) res[1][57]=a12;
  a26=(a26-a17);
  if (res[1]!=0) res[1][58]=a26;
  if (res[1]!=0) res[1][59]=a07;
  if (res[1]!=0) res[1][60]=a27;
  if (res[1]!=0) res[1][61]=a27;
  if (res[1]!=0) res[1][62]=a27;
  if (res[1]!=0) res[1][63]=a27;
  if (res[1]!=0) res[1][64]=a27;
  if (res[1]!=0) res[1][65]=a27;
  if (res[1]!=0) res[1][66]=a27;
  if (res[1]!=0) res[1][67]=a27;
  if (res[1]!=0) res[1][68]=a27;
  a31=(-a31);
  if (res[1]!=0) res[1][69]=a31;
  if (res[1]!=0) res[1][70]=a32;
  if (res[1]!=0) res[1][71]=a07;
  a07=arg[1]? arg[1][16] : 0;
  if (res[2]!=0) res[2][0]=a07;
  if (res[2]!=0) res[2][1]=a27;
  a32=arg[1]? arg[1][20] : 0;
  a31=(a32*a30);
  a26=arg[1]? arg[1][19] : 0;
  a17=(a26*a21);
  a17=(a31+a17);
  a12=arg[1]? arg[1][18] : 0;
  a22=(a12*a11);
  a22=(a17+a22);
  a23=arg[1]? arg[1][17] : 0;
  a19=(a23*a10);
  a19=(a22+a19);
  a19=(-a19);
  if (res[2]!=0) res[2][2]=a19;
  a06=(-a22);
  if (res[2]!=0) res[2][3]=a06;
  a15=(-a17);
  if (res[2]!=0) res[2][4]=a15;
  a24=(-a31);
  if (res[2]!=0) res[2][5]=a24;
  if (res[2]!=0) res[2][6]=a27;
  if (res[2]!=0) res[2][7]=a07;
  a32=(a32*a29);
  a26=(a26*a20);
  a26=(a32+a26);
  a12=(a12*a09);
  a12=(a26+a12);
  a23=(a23*a03);
  a23=(a12+a23);
  if (res[2]!=0) res[2][8]=a23;
  if (res[2]!=0) res[2][9]=a12;
  if (res[2]!=0) res[2][10]=a26;
  if (res[2]!=0) res[2][11]=a32;
  if (res[2]!=0) res[2][12]=a19;
  if (res[2]!=0) res[2][13]=a23;
  a23=(a20*a18);
  a23=(a32*a23);
  a18=(a21*a18);
  a18=(a31*a18);
  a23=(a23+a18);
  a18=arg[1]? arg[1][34] : 0;
  a19=(a23+a18);
  a23=(a19+a23);
  a07=arg[1]? arg[1][33] : 0;
  a23=(a23+a07);
  a07=(a09*a02);
  a27=(a26*a07);
  a02=(a11*a02);
  a25=(a17*a02);
  a27=(a27+a25);
  a25=(a23+a27);
  a27=(a25+a27);
  a13=arg[1]? arg[1][32] : 0;
  a27=(a27+a13);
  a13=(a12*a05);
  a22=(a22*a04);
  a13=(a13+a22);
  a22=(a27+a13);
  a13=(a22+a13);
  a08=arg[1]? arg[1][31] : 0;
  a13=(a13+a08);
  if (res[2]!=0) res[2][14]=a13;
  if (res[2]!=0) res[2][15]=a22;
  a13=(a26*a05);
  a17=(a17*a04);
  a13=(a13+a17);
  a13=(a25+a13);
  if (res[2]!=0) res[2][16]=a13;
  a07=(a32*a07);
  a02=(a31*a02);
  a07=(a07+a02);
  a07=(a19+a07);
  a05=(a32*a05);
  a31=(a31*a04);
  a05=(a05+a31);
  a05=(a07+a05);
  if (res[2]!=0) res[2][17]=a05;
  if (res[2]!=0) res[2][18]=a06;
  if (res[2]!=0) res[2][19]=a12;
  if (res[2]!=0) res[2][20]=a22;
  if (res[2]!=0) res[2][21]=a27;
  if (res[2]!=0) res[2][22]=a25;
  if (res[2]!=0) res[2][23]=a07;
  if (res[2]!=0) res[2][24]=a15;
  if (res[2]!=0) res[2][25]=a26;
  if (res[2]!=0) res[2][26]=a13;
  if (res[2]!=0) res[2][27]=a25;
  if (res[2]!=0) res[2][28]=a23;
  if (res[2]!=0) res[2][29]=a19;
  if (res[2]!=0) res[2][30]=a24;
  if (res[2]!=0) res[2][31]=a32;
  if (res[2]!=0) res[2][32]=a05;
  if (res[2]!=0) res[2][33]=a07;
  if (res[2]!=0) res[2][34]=a19;
  if (res[2]!=0) res[2][35]=a18;
  if (res[3]!=0) res[3][0]=a03;
  if (res[3]!=0) res[3][1]=a10;
  if (res[3]!=0) res[3][2]=a09;
  if (res[3]!=0) res[3][3]=a11;
  if (res[3]!=0) res[3][4]=a20;
  if (res[3]!=0) res[3][5]=a21;
  if (res[3]!=0) res[3][6]=a29;
  if (res[3]!=0) res[3][7]=a30;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na3_scene_kinematics(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_na3_scene_kinematics_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_na3_scene_kinematics_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_na3_scene_kinematics_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_na3_scene_kinematics_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na3_scene_kinematics_n_in(void) { return 2;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_na3_scene_kinematics_n_out(void) { return 4;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_na3_scene_kinematics_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na3_scene_kinematics_name_in(casadi_int i) {
  switch (i) {
    case 0: return "q";
    case 1: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_na3_scene_kinematics_name_out(casadi_int i) {
  switch (i) {
    case 0: return "poses";
    case 1: return "J";
    case 2: return "M";
    case 3: return "cs";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na3_scene_kinematics_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_na3_scene_kinematics_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s2;
    case 1: return casadi_s3;
    case 2: return casadi_s4;
    case 3: return casadi_s5;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_na3_scene_kinematics_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2;
  if (sz_res) *sz_res = 4;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_na3_scene_kinematics_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 2*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 4*sizeof(casadi_real*);
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

CASADI_SYMBOL_EXPORT int snakecg_na3_batch_scene_kinematics(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[2];
  casadi_real* r[4];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 34);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 2; ++k) a[k] = 0;
  for (k = 0; k < 4; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    r[0] = res[0] + i * 12;
    r[1] = res[1] + i * 72;
    r[2] = res[2] + i * 36;
    r[3] = res[3] + i * 8;
    if (snakecg_na3_scene_kinematics(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
