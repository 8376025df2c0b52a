MODULE DataSocket
    ! Tests: SocketReceive \Data stores the bytes received from the array's first element
    ! on (\ReadNoOfBytes of them, the rest of the stream pending for the next receive) and
    ! \NoRecBytes counts them; SocketSend \Data sends the array (\NoOfBytes: its first
    ! elements). An element beyond 0..255 is no byte: ERR_ARGVALERR (rapidmc's reading; the
    ! manual names only the byte type). Messages: lines of stdin, hex pairs as bytes.
    VAR socketdev server;
    VAR socketdev client;
    VAR byte request{4} := [0, 0, 0, 0];
    VAR byte reply{3} := [1, 2, 255];
    VAR num got := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 11000;
        SocketListen server;
        SocketAccept server, client;
        SocketReceive client \Data:=request \ReadNoOfBytes:=2 \NoRecBytes:=got;
        TPWrite "got " \Num:=got;
        TPWrite "first " \Num:=request{1};
        TPWrite "second " \Num:=request{2};
        TPWrite "third " \Num:=request{3};
        SocketReceive client \Data:=request \NoRecBytes:=got;
        TPWrite "then " \Num:=got;
        TPWrite "first " \Num:=request{1};
        SocketSend client \Data:=reply;
        SocketSend client \Data:=reply \NoOfBytes:=2;
        reply{2} := 300;
        SocketSend client \Data:=reply;
    ENDPROC
ENDMODULE
