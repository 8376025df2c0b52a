MODULE Robot
    ! Written for the test (issue 28): the robot task meets the master at each job.
    VAR syncident job_a;
    VAR syncident job_b;
    VAR syncident job_c;
    VAR syncident job_d;
    VAR syncident job_e;
    PERS tasks both{2} := [["T_MASTER"], ["T_ROB"]];

    PROC main()
        WHILE TRUE DO
            WaitSyncTask job_a, both;
        ENDWHILE
    ENDPROC
ENDMODULE
