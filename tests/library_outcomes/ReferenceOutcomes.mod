MODULE ReferenceOutcomes
  ! Tests: outcomes of names added for the reference (issue 8, item 1) when model checking:
  ! SearchExtJ hits or misses (ERR_WHLSEARCH); a UDP datagram arrives (SocketReceiveFrom)
  ! or the wait times out (ERR_SOCK_TIMEOUT).  Each result lands in a PERS.
  PERS num nSearch := 0;
  PERS num nDatagram := 0;
  CONST jointtarget jExt := [[0,0,0,0,0,0],[250,9E9,9E9,9E9,9E9,9E9]];
  VAR jointtarget jFound;
  VAR socketdev udp;

  PROC main()
    Probe;
    Listen;
  ENDPROC

  PROC Probe()
    SearchExtJ \Stop, diProbe, jFound, jExt, v100;
    nSearch := 1;
  ERROR
    IF ERRNO = ERR_WHLSEARCH THEN
      nSearch := 2;
      RETURN;
    ENDIF
  ENDPROC

  PROC Listen()
    VAR string text;
    VAR string sender;
    VAR num port;
    SocketCreate udp \UDP;
    SocketBind udp, "127.0.0.1", 3000;
    SocketReceiveFrom udp \Str:=text, sender, port \Time:=2;
    nDatagram := 1;
  ERROR
    IF ERRNO = ERR_SOCK_TIMEOUT THEN
      nDatagram := 2;
      RETURN;
    ENDIF
  ENDPROC
ENDMODULE
