MODULE Missing
  ! Declarations written by 'rapidmc stubs' for the names the program uses and no module declares.
  ! Types come from the uses; values are neutral: replace them with the cell's real data.

  ! ReadScale: first use prog.mod:6:24 (assigned to num data)
  FUNC num ReadScale()
    RETURN 0;
  ENDFUNC
ENDMODULE
