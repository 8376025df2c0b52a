! expect: exit 1 [RMC301]
! A literal beyond the num range passed to a num parameter: ERR_NUM_LIMIT when the call
! runs (the linker once raised it while compiling: internal error).
MODULE NumTooLarge
  PROC main()
    TPWrite "before";
    TPWrite "shifted" \Num:=BitRSh(255, 1E308);
  ENDPROC
ENDMODULE
