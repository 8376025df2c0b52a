MODULE MainModule
  ! Tests: \Num and \Bool of TPWrite are alternatives (\Num | \Bool | ...): giving both is a
  ! static argument error.
  PROC main()
    TPWrite "must not run";
    TPWrite "x" \Num:=1 \Bool:=TRUE;
  ENDPROC
ENDMODULE
