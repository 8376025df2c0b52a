MODULE InterruptCounts
  ! Written for the distributed search's node codec: a free input (a part sensor) raises
  ! an interrupt whose trap counts and logs, so the model has no packed table and its
  ! states travel as the node ids of their parts (distributed/codec.py, NodeCodec).
  VAR intnum iPart;
  VAR num nParts := 0;
  VAR num nCycles := 0;
  VAR num log{2} := [0, 0];
  CONST robtarget pA := [[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC main()
    CONNECT iPart WITH OnPart;
    ISignalDI diPart, 1, iPart;
    WHILE TRUE DO
      MoveJ pA, v1000, z10, tool0;
      nCycles := (nCycles + 1) MOD 3;
    ENDWHILE
  ENDPROC

  TRAP OnPart
    nParts := (nParts + 1) MOD 3;
    log{1 + nParts DIV 2} := nCycles;
  ENDTRAP
ENDMODULE
