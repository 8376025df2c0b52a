MODULE MainModule
  ! Tests: TPErase clears the FlexPendant window and writes nothing to the output.
  PROC main()
    TPWrite "first";
    TPErase;
    TPWrite "second";
    TPErase;
  ENDPROC
ENDMODULE
