MODULE DeadDataRequestString
    ! A socket server as the public ones are written: each request is received into a
    ! module string, parsed, answered with a reply string built from it, and the loop's
    ! ERROR handler reconnects on a closed socket and RETRYs the receive.  The request is
    ! written whole by the next SocketReceive and the reply by the next answer, so both
    ! are dead between their last read and their next write, on the handler's paths too.
    ! (A handler that went on with TRYNEXT after a failed receive would parse the old
    ! request again: there the request stays live.)
    VAR socketdev client;
    VAR string request := "";
    VAR string reply := "";
    VAR num code := 0;
    VAR bool known := FALSE;
    VAR num served := 0;

    PROC main()
        OpenLink;
        WHILE TRUE DO
            SocketReceive client \Str:=request \Time:=WAIT_MAX;
            known := StrToVal(request, code);
            IF NOT known code := -1;
            reply := NumToStr(code, 0);
            IF code = 2 reply := "moved";
            SocketSend client \Str:=reply;
            IF code = 2 served := 1;
        ENDWHILE
    ERROR
        IF ERRNO = ERR_SOCK_CLOSED THEN
            SocketClose client;
            OpenLink;
        ENDIF
        RETRY;
    ENDPROC

    PROC OpenLink()
        SocketCreate client;
        SocketConnect client, "10.0.0.2", 5000 \Time:=WAIT_MAX;
    ENDPROC
ENDMODULE
