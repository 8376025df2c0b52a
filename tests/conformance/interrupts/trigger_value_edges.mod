MODULE trigger_value_edges
  ! Tests: ISignalDO TriggValue 0 fires on falling edges only, 1 on rising
  ! edges only, 2 (edge) on both.
  VAR signaldo doF;
  VAR signaldo doR;
  VAR signaldo doE;
  VAR intnum irF;
  VAR intnum irR;
  VAR intnum irE;
  VAR num falls := 0;
  VAR num rises := 0;
  VAR num edges := 0;
  PROC main()
    AliasIO "DOF", doF;
    AliasIO "DOR", doR;
    AliasIO "DOE", doE;
    CONNECT irF WITH onFall;
    CONNECT irR WITH onRise;
    CONNECT irE WITH onEdge;
    ISignalDO doF, 0, irF;
    ISignalDO doR, 1, irR;
    ISignalDO doE, 2, irE;
    SetDO doF, 1;
    SetDO doF, 0;
    SetDO doF, 1;
    SetDO doR, 1;
    SetDO doR, 0;
    SetDO doR, 1;
    SetDO doE, 1;
    SetDO doE, 0;
    SetDO doE, 1;
    TPWrite "falls=" \Num:=falls;
    TPWrite "rises=" \Num:=rises;
    TPWrite "edges=" \Num:=edges;
  ENDPROC
  TRAP onFall
    falls := falls + 1;
  ENDTRAP
  TRAP onRise
    rises := rises + 1;
  ENDTRAP
  TRAP onEdge
    edges := edges + 1;
  ENDTRAP
ENDMODULE
