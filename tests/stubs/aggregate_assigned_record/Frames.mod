MODULE Frames
  ! Tests: stubs for a packet module that was not given: a frame's header is set whole
  ! from a four-part aggregate, then its sequence number is read and stepped by name (a
  ! held-out network module). The header's record takes four components, the names read
  ! first; with only the names read it had two, and the module did not load (RMC206).
  PERS frame_t gFrame;

  PROC main()
    gFrame.Header := [FRAME_START, 96, 1, 0];
    gFrame.Header.Seq := gFrame.Header.Seq + 1;
    IF gFrame.Header.Cmd > 0 gFrame.Header.Cmd := 0;
  ENDPROC
ENDMODULE
