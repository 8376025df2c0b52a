MODULE MainModule
  ! Tests: VectMagn is the Euclidean length of a pos vector.
  PROC main()
    VAR pos v := [1, 2, 2];
    TPWrite "345=" \Num:=VectMagn([3, 4, 0]);
    TPWrite "122=" \Num:=VectMagn(v);
    TPWrite "zero=" \Num:=VectMagn([0, 0, 0]);
    TPWrite "neg=" \Num:=VectMagn([0, -6, -8]);
  ENDPROC
ENDMODULE
