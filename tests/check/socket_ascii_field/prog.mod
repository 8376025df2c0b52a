MODULE SocketAsciiField
    ! A command letter read from raw bytes with UnpackRawBytes \ASCII:=1, compared with
    ! "S" and "R": each letter, written at byte 1 of a message, takes its branch.  The
    ! four-letter "STOP" never equals one character and gives no message.
    VAR socketdev server;
    VAR socketdev client;
    VAR rawbytes data;
    VAR string command;
    VAR num handled := 0;

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 5503;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \RawData:=data \Time:=WAIT_MAX;
            UnpackRawBytes data, 1, command \ASCII:=1;
            IF command = "S" THEN
                handled := 1;
            ELSEIF command = "R" THEN
                handled := 2;
            ELSEIF command = "STOP" THEN
                handled := 3;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
