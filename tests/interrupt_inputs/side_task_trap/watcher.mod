MODULE Watcher
    VAR intnum stop_int;
    PERS bool stopped;

    PROC main()
        CONNECT stop_int WITH OnStop;
        ISignalDI diReset, 1, stop_int;
        WHILE TRUE DO
            WaitTime 1;
        ENDWHILE
    ENDPROC

    TRAP OnStop
        stopped := TRUE;
    ENDTRAP
ENDMODULE
