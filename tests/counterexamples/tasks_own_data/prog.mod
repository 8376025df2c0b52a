MODULE ServerA
    ! Two tasks run the same set-up routine and have data of the same names. The error is
    ! this task's: the headline shows its own count (0), not the other task's (2), and the
    ! other task's steps are one line, since they write only that task's data.
    VAR socketdev server_socket;
    VAR num count := 0;

    PROC main()
        init_socket server_socket, 1000;
        count := 10 / count;
    ENDPROC
ENDMODULE
