MODULE MainModule
  ! Tests: VectMagn takes a pos; a num is a static type error.
  PROC main()
    VAR num m;
    TPWrite "must not run";
    m := VectMagn(5);
  ENDPROC
ENDMODULE
