MODULE prog
  ! The UNDO handler calls a clean-up routine that ends the program with EXIT (a public
  ! socket server closes its sockets so). The handler runs once; before, the EXIT inside
  ! it ran the same UNDO handler again without end (RMC305, nesting too deep).
  VAR num opened;

  PROC main()
    opened := 1;
    EXIT;
  UNDO
    CloseAll;
  ENDPROC

  PROC CloseAll()
    opened := 0;
    EXIT;
  ENDPROC
ENDMODULE
