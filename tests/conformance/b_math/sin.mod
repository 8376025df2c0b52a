MODULE MainModule
  ! Tests: Sin takes its angle in degrees.
  PROC main()
    TPWrite "sin30=" \Num:=Round(Sin(30) \Dec:=4);
    TPWrite "sin90=" \Num:=Round(Sin(90) \Dec:=4);
    TPWrite "sinm30=" \Num:=Round(Sin(-30) \Dec:=4);
    TPWrite "sin45=" \Num:=Round(Sin(45) \Dec:=4);
  ENDPROC
ENDMODULE
