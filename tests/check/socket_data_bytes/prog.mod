MODULE DataServer
    ! A server reads a 2-byte command into an array of byte: byte 1 is the command
    ! (1: pick, 2: place, "s" written as StrToByte: stop), byte 2 a count; it answers with
    ! a 3-byte status.
    VAR socketdev server;
    VAR socketdev client;
    VAR byte request{4};
    VAR byte reply{3} := [0, 0, 0];
    VAR num picked := 0;
    VAR num placed := 0;
    VAR num stopped := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 11000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Data:=request \ReadNoOfBytes:=2 \Time:=WAIT_MAX;
            IF request{1} = 1 THEN
                picked := picked + 1;
                IF picked > 3 picked := 0;
                reply{1} := 1;
            ELSEIF request{1} = 2 THEN
                placed := 1;
                reply{1} := 2;
            ELSEIF request{1} = StrToByte("s" \Char) THEN
                stopped := 1;
            ELSE
                reply{1} := 255;
            ENDIF
            SocketSend client \Data:=reply;
        ENDWHILE
    ENDPROC
ENDMODULE
