MODULE MainModule
  ! Tests: NumToStr with \Exp writes scientific notation (manual example "3.85E-01").
  PROC main()
    TPWrite NumToStr(0.38521, 2 \Exp);
  ENDPROC
ENDMODULE
